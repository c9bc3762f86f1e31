// `snell run` with expectation files, reruns, results.csv, shards and
// `snell merge`, interruption and --resume, as a user runs them.
#include <fcntl.h>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <thread>

#include "snell_process.h"

namespace {

namespace fs = std::filesystem;

using snell::testing::Outcome;
using snell::testing::readText;
using snell::testing::spawnSnell;

Outcome snell(const std::string& args) { return snell::testing::runSnell(args); }

std::vector<nlohmann::json> records(const fs::path& path) {
  std::vector<nlohmann::json> out;
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) out.push_back(nlohmann::json::parse(line));
  return out;
}

class Scratch {
 public:
  Scratch()
      : dir_(fs::temp_directory_path() / fmt::format("snell-baseline-cli-{}-{}", getpid(), n_++)) {
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  ~Scratch() { fs::remove_all(dir_); }
  fs::path operator/(const std::string& name) const { return dir_ / name; }
  const fs::path& path() const { return dir_; }

 private:
  static inline int n_ = 0;
  fs::path dir_;
};

// Listing 14.1 with Eta changed in the shader only: its cases Fail on the
// vectors (the oracle reads the manifest's 0.66).
fs::path brokenFresnel(const Scratch& scratch) {
  const fs::path dir = scratch / "shaders";
  fs::create_directories(dir);
  fs::copy(SNELL_SOURCE_ROOT "/shaders/orange-book/14.1-fresnel", dir / "fresnel");
  std::string text = readText(dir / "fresnel" / "fresnel.vert");
  const std::string from = "const float Eta = 0.66;";
  text.replace(text.find(from), from.size(), "const float Eta = 0.67;");
  std::ofstream(dir / "fresnel" / "fresnel.vert", std::ios::trunc) << text;
  return dir;
}

TEST(BaselineCli, KnownFailuresPassTheGateAndTheRestIsReported) {
  Scratch scratch;
  const fs::path shaders = brokenFresnel(scratch);
  const std::string common = fmt::format("run --backend gl -j 2 --shaders {} --out {}",
                                         shaders.string(), (scratch / "out").string());
  // No expectations: the failure fails the gate, after one rerun.
  const Outcome plain = snell(
      fmt::format("{} --filter '*/sweep' --json {}", common, (scratch / "plain.jsonl").string()));
  EXPECT_EQ(plain.code, 1) << plain.out;
  const auto first = records(scratch / "plain.jsonl");
  ASSERT_EQ(first.size(), 1u);
  EXPECT_EQ(first[0]["status"], "Fail");
  EXPECT_EQ(first[0]["reruns"], nlohmann::json::array({"Fail"}));
  EXPECT_EQ(readText(scratch / "plain.csv").rfind("gl/orange-book/14.1-fresnel/sweep,Fail,", 0), 0u)
      << readText(scratch / "plain.csv");

  // Listed as a known failure, with an entry that no longer fails and one
  // for a case that did not run: exit 0, both reported.
  fs::create_directories(scratch / "expect");
  std::ofstream(scratch / "expect" / "gl-fails.txt")
      << "# reason: Eta edited in the shader\n# expires: 2999-01-01\n"
         "orange-book/14.1-fresnel/sweep,Fail\n"
         "orange-book/14.1-fresnel/sphere,Fail\n";
  const Outcome expected =
      snell(fmt::format("{} --filter 'orange-book/14.1-fresnel/s[pw]*' --json {} --junit {} "
                        "--expectations {}",
                        common, (scratch / "expected.jsonl").string(),
                        (scratch / "expected.xml").string(), (scratch / "expect").string()));
  // The sphere case also fails (same edit): it is listed, so only the
  // torus is absent.
  EXPECT_EQ(expected.code, 0) << expected.out;
  EXPECT_NE(expected.out.find("0 unexpected failures, 2 expected failures"), std::string::npos)
      << expected.out;
  const std::string csv = readText(scratch / "expected.csv");
  EXPECT_NE(csv.find("gl/orange-book/14.1-fresnel/sweep,ExpectedFail,"), std::string::npos) << csv;
  EXPECT_NE(readText(scratch / "expected.xml").find("<skipped message=\"Fail: expected failure"),
            std::string::npos);

  // The entry that passes now, for a case that passes: an improvement,
  // with the line to delete.
  std::ofstream(scratch / "expect" / "gl-fails.txt", std::ios::trunc)
      << "orange-book/14.1-fresnel/sweep,Fail\norange-book/14.1-fresnel/torus,Fail\n"
         "orange-book/14.1-fresnel/gone,Crash\n";
  const Outcome improved =
      snell(fmt::format("run --backend gl -j 2 --filter 'orange-book/14.1-fresnel/[st][pwo]*' "
                        "--out {} --expectations {}",
                        (scratch / "out2").string(), (scratch / "expect").string()));
  EXPECT_EQ(improved.code, 0) << improved.out;
  EXPECT_NE(improved.out.find("improvement: gl orange-book/14.1-fresnel/sweep is Pass; delete "),
            std::string::npos)
      << improved.out;
  EXPECT_NE(improved.out.find("gl-fails.txt:1 `orange-book/14.1-fresnel/sweep,Fail`"),
            std::string::npos)
      << improved.out;
  EXPECT_NE(improved.out.find("absent: gl orange-book/14.1-fresnel/gone"), std::string::npos)
      << improved.out;
}

TEST(BaselineCli, ExpiredEntryStopsTheRunBeforeAnyDriverLoads) {
  Scratch scratch;
  std::ofstream(scratch / "softpipe-fails.txt")
      << "# reason: waits for a Mesa fix\n# expires: "
         "2001-01-01\norange-book/14.1-fresnel/sweep,Fail\n";
  const Outcome o =
      snell(fmt::format("run --backend gl --filter 'orange-book/14.1-fresnel/[st][pwo]*' "
                        "--expectations {} --json {}",
                        (scratch / "softpipe-fails.txt").string(), (scratch / "r.jsonl").string()));
  EXPECT_EQ(o.code, 2) << o.out;
  EXPECT_NE(o.out.find("softpipe-fails.txt:3: this entry expired on 2001-01-01"), std::string::npos)
      << o.out;
  EXPECT_FALSE(fs::exists(scratch / "r.jsonl.partial"));
}

TEST(BaselineCli, SkippedCasesDoNotRun) {
  Scratch scratch;
  std::ofstream(scratch / "x-skips.txt") << "# reason: slow here\n/sweep$\n";
  const Outcome o =
      snell(fmt::format("run --backend gl --filter 'orange-book/14.1-fresnel/[st][pwo]*' "
                        "--expectations {} --json {} --out {}",
                        (scratch / "x-skips.txt").string(), (scratch / "r.jsonl").string(),
                        (scratch / "out").string()));
  EXPECT_EQ(o.code, 0) << o.out;
  EXPECT_EQ(records(scratch / "r.jsonl").size(), 2u);
  EXPECT_NE(o.out.find("skipped: gl orange-book/14.1-fresnel/sweep"), std::string::npos) << o.out;
}

// The CI example gates softpipe with the shipped file: it must name every
// case softpipe fails on the whole catalog, and no more (an entry that
// passes is an improvement, exit 1 as well). Its entries expire so that a
// person looks at them again; this test checks what they say, not when, so
// that an unchanged tree does not start failing on a date.
TEST(BaselineCli, TheShippedSoftpipeExpectationsHoldForTheWholeCatalog) {
  Scratch scratch;
  const std::string shipped = readText(SNELL_SOURCE_ROOT "/ci/expectations/softpipe-fails.txt");
  ASSERT_NE(shipped.find("# expires: "), std::string::npos);
  std::ofstream(scratch / "softpipe-fails.txt")
      << std::regex_replace(shipped, std::regex("# expires: [0-9-]+"), "# expires: 9999-12-31");
  const Outcome o =
      snell(fmt::format("run --backend gl:softpipe --expectations {} --json {} --out {}",
                        (scratch / "softpipe-fails.txt").string(), (scratch / "r.jsonl").string(),
                        (scratch / "out").string()));
  EXPECT_EQ(o.code, 0) << o.out;
  EXPECT_NE(o.out.find("expected: gl:softpipe learnopengl/reflection/torus is Fail"),
            std::string::npos)
      << o.out;
}

// A catalog of Listing 14.1 alone, in scratch/shaders (fresnel/), for tests
// that edit a listing or interrupt a run.
fs::path fresnelCatalogIn(const Scratch& scratch) {
  const fs::path shaders = scratch / "shaders";
  fs::create_directories(shaders);
  fs::copy(SNELL_SOURCE_ROOT "/shaders/orange-book/14.1-fresnel", shaders / "fresnel");
  return shaders;
}

// Results with the timings taken out: what must match between runs.
std::vector<nlohmann::json> withoutTimings(std::vector<nlohmann::json> results) {
  for (nlohmann::json& r : results)
    for (const char* key : {"seconds", "backend_seconds", "oracle_seconds", "phases",
                            "oracle_results", "oracle_stored"})
      r.erase(key);
  return results;
}

TEST(BaselineCli, ShardsAndBackendJobsMergedEqualOneUnshardedRun) {
  Scratch scratch;
  const std::string filter = "--filter 'orange-book/14.1-fresnel/[st][pwo]*' -j 2";
  const Outcome whole =
      snell(fmt::format("run {} --out {} --json {}", filter, (scratch / "out-whole").string(),
                        (scratch / "whole.jsonl").string()));
  ASSERT_EQ(whole.code, 0) << whole.out;
  // OpenGL in two shards, Vulkan in a job of its own: the OpenGL-Vulkan
  // image comparison can only happen in the merge.
  const std::string out = (scratch / "out-split").string();
  const std::vector<std::pair<std::string, std::string>> jobs = {
      {"--backend gl --shard 1/2", "job1.jsonl"},
      {"--backend gl --shard 2/2", "job2.jsonl"},
      {"--backend vk", "jobv.jsonl"}};
  for (const auto& [job, file] : jobs) {
    const Outcome o = snell(
        fmt::format("run {} {} --out {} --json {}", filter, job, out, (scratch / file).string()));
    ASSERT_EQ(o.code, 0) << job << "\n" << o.out;
  }
  EXPECT_EQ(records(scratch / "job1.jsonl").size(), 2u);  // cases 1 and 3
  EXPECT_EQ(records(scratch / "job2.jsonl").size(), 1u);
  const Outcome merged = snell(
      fmt::format("merge {} {} {} --out {} --json {} --junit {}", (scratch / "job2.jsonl").string(),
                  (scratch / "jobv.jsonl").string(), (scratch / "job1.jsonl").string(), out,
                  (scratch / "merged.jsonl").string(), (scratch / "merged.xml").string()));
  ASSERT_EQ(merged.code, 0) << merged.out;
  const auto a = withoutTimings(records(scratch / "whole.jsonl"));
  const auto b = withoutTimings(records(scratch / "merged.jsonl"));
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) EXPECT_EQ(a[k], b[k]) << k;
  EXPECT_TRUE(fs::exists(scratch / "merged.csv"));
  EXPECT_TRUE(fs::exists(scratch / "merged.xml"));
  // A run whose backends were compared already merges into itself: no
  // comparison is made twice, and no image is read (so none is needed).
  const Outcome alone =
      snell(fmt::format("merge {} --json {} --out {}", (scratch / "whole.jsonl").string(),
                        (scratch / "alone.jsonl").string(), (scratch / "no-images").string()));
  ASSERT_EQ(alone.code, 0) << alone.out;
  const auto c = withoutTimings(records(scratch / "alone.jsonl"));
  ASSERT_EQ(a.size(), c.size());
  for (std::size_t k = 0; k < a.size(); ++k) EXPECT_EQ(a[k], c[k]) << k;
  // An output on an input, or two outputs on one file, is refused before
  // anything is written.
  const std::string job1 = (scratch / "job1.jsonl").string();
  const std::string before = readText(job1);
  const Outcome onInput = snell(fmt::format("merge {0} --json {0}", job1));
  EXPECT_EQ(onInput.code, 2) << onInput.out;
  EXPECT_NE(onInput.out.find("would destroy that input"), std::string::npos) << onInput.out;
  EXPECT_EQ(readText(job1), before);
  const Outcome onEachOther = snell(
      fmt::format("merge {0} --json {1} --junit {1}", job1, (scratch / "same.jsonl").string()));
  EXPECT_EQ(onEachOther.code, 2) << onEachOther.out;
  EXPECT_FALSE(fs::exists(scratch / "same.jsonl"));
  // One file given twice is refused as such (an empty one counted as two
  // shards), and overlapping shards are refused.
  const Outcome twice =
      snell(fmt::format("merge {} {} --json {}", (scratch / "job1.jsonl").string(),
                        (scratch / "job1.jsonl").string(), (scratch / "bad.jsonl").string()));
  EXPECT_EQ(twice.code, 2) << twice.out;
  EXPECT_NE(twice.out.find("are one file, given twice"), std::string::npos) << twice.out;
  fs::copy_file(scratch / "job1.jsonl", scratch / "job1-copy.jsonl");
  const Outcome overlap =
      snell(fmt::format("merge {} {} --json {}", (scratch / "job1.jsonl").string(),
                        (scratch / "job1-copy.jsonl").string(), (scratch / "bad.jsonl").string()));
  EXPECT_EQ(overlap.code, 2) << overlap.out;
  EXPECT_NE(overlap.out.find("shards must not overlap"), std::string::npos) << overlap.out;
  // A damaged image was compared as a difference between the drivers (a
  // CompatibilityWarning on both, exit 0): it is exit 2, naming it.
  fs::path damaged;
  for (const auto& entry : fs::recursive_directory_iterator(out))
    if (entry.path().filename() == "vk.exr") damaged = entry.path();
  ASSERT_FALSE(damaged.empty());
  // So is an image that is not the one its shard recorded (another run's,
  // here the reference itself, 0 from it where the shard recorded more):
  // it was compared across the APIs as the shard's, and the merge passed.
  double recorded = 0;
  for (const nlohmann::json& r : records(scratch / "jobv.jsonl"))
    for (const nlohmann::json& image : r["images"])
      if (image["against"] == "reference") recorded = image["max_error"].get<double>();
  ASSERT_GT(recorded, 1e-6);  // lavapipe's image is not the reference, bit for bit
  const fs::path kept = scratch / "vk-kept.exr";
  fs::copy_file(damaged, kept);
  fs::copy_file(damaged.parent_path() / "reference.exr", damaged,
                fs::copy_options::overwrite_existing);
  const Outcome stale =
      snell(fmt::format("merge {} {} {} --out {} --json {}", (scratch / "job2.jsonl").string(),
                        (scratch / "jobv.jsonl").string(), (scratch / "job1.jsonl").string(), out,
                        (scratch / "stale.jsonl").string()));
  EXPECT_EQ(stale.code, 2) << stale.out;
  EXPECT_NE(stale.out.find(damaged.string() + ": not the image the shard recorded"),
            std::string::npos)
      << stale.out;
  EXPECT_FALSE(fs::exists(scratch / "stale.jsonl"));
  fs::copy_file(kept, damaged, fs::copy_options::overwrite_existing);
  fs::resize_file(damaged, 500);
  const Outcome broken =
      snell(fmt::format("merge {} {} {} --out {} --json {}", (scratch / "job2.jsonl").string(),
                        (scratch / "jobv.jsonl").string(), (scratch / "job1.jsonl").string(), out,
                        (scratch / "broken.jsonl").string()));
  EXPECT_EQ(broken.code, 2) << broken.out;
  EXPECT_NE(broken.out.find(damaged.string() + ": cannot be read"), std::string::npos)
      << broken.out;
  EXPECT_FALSE(fs::exists(scratch / "broken.jsonl"));
}

// A shard run on another text of a listing (edited since, another
// commit's) did not run what the other shards ran: the merge refuses it,
// naming the file, the case and the listing.
TEST(BaselineCli, AShardRunOnAnotherTextOfAListingIsRefused) {
  Scratch scratch;
  const fs::path shaders = fresnelCatalogIn(scratch);
  const auto shard = [&](const std::string& which, const std::string& file) {
    const Outcome o = snell(fmt::format(
        "run --shaders {} --filter '*/s[wt]*' --backend gl --shard {} --out {} --json {}",
        shaders.string(), which, (scratch / "out").string(), (scratch / file).string()));
    ASSERT_EQ(o.code, 0) << o.out;
  };
  const auto merge = [&](const std::string& second) {
    return snell(fmt::format("merge {} {} --shaders {} --json {}", (scratch / "s1.jsonl").string(),
                             (scratch / second).string(), shaders.string(),
                             (scratch / "merged.jsonl").string()));
  };
  shard("1/2", "s1.jsonl");
  shard("2/2", "s2.jsonl");
  const Outcome same = merge("s2.jsonl");
  EXPECT_EQ(same.code, 0) << same.out;
  // The vertex stage gains a comment: the same shader to a driver, another
  // text to a merge, which cannot tell what else changed.
  std::ofstream(shaders / "fresnel" / "fresnel.vert", std::ios::app) << "// edited\n";
  shard("2/2", "s2-edited.jsonl");
  fs::remove(scratch / "merged.jsonl");
  const Outcome mixed = merge("s2-edited.jsonl");
  EXPECT_EQ(mixed.code, 2) << mixed.out;
  EXPECT_NE(mixed.out.find((scratch / "s1.jsonl").string() + ": ran orange-book/14.1-fresnel/"),
            std::string::npos)
      << mixed.out;
  EXPECT_NE(mixed.out.find("from another text of its listing"), std::string::npos) << mixed.out;
  EXPECT_FALSE(fs::exists(scratch / "merged.jsonl"));
}

// A resumed run keeps the cases its interrupted run finished, but not one
// that ran another text of its listing (edited since): that one runs
// again, with a note.
TEST(BaselineCli, AResumedCaseOfAnEditedListingRunsAgain) {
  Scratch scratch;
  const fs::path shaders = fresnelCatalogIn(scratch);
  const std::string run = fmt::format("run --shaders {} --filter '*/s[wt]*' --backend gl --out {}",
                                      shaders.string(), (scratch / "out").string());
  const Outcome whole = snell(run + " --json " + (scratch / "whole.jsonl").string());
  ASSERT_EQ(whole.code, 0) << whole.out;
  // The run as if interrupted after its first case.
  nlohmann::json first = records(scratch / "whole.jsonl").front();
  first["incomplete"] = true;
  std::ofstream(scratch / "cut.jsonl") << first.dump() << "\n";
  const std::string id = first["case"];
  const std::string resume = fmt::format(" --resume {} --json ", (scratch / "cut.jsonl").string());
  const Outcome kept = snell(run + resume + (scratch / "kept.jsonl").string());
  ASSERT_EQ(kept.code, 0) << kept.out;
  EXPECT_EQ(kept.out.find("[1/2] gl " + id), std::string::npos) << kept.out;  // not run again
  std::ofstream(shaders / "fresnel" / "fresnel.vert", std::ios::app) << "// edited\n";
  const Outcome edited = snell(run + resume + (scratch / "edited.jsonl").string());
  ASSERT_EQ(edited.code, 0) << edited.out;
  EXPECT_NE(edited.out.find(id + " on gl ran another text of its listing"), std::string::npos)
      << edited.out;
  EXPECT_NE(edited.out.find("gl " + id + " Pass"), std::string::npos) << edited.out;
}

std::size_t lineCount(const fs::path& path) {
  std::ifstream in(path);
  std::size_t n = 0;
  for (std::string line; std::getline(in, line);) n += line.empty() ? 0 : 1;
  return n;
}

// `snell args`, whose --json is `json` and whose stderr goes to `err`,
// with `edit` made as soon as its first record is streamed (or the run has
// ended, if it ends first): the records streamed before the edit, and the
// run's exit status.
struct EditedRun {
  std::size_t recordsBeforeEdit = 0;
  int status = 0;
};
EditedRun runEditingAfterTheFirstRecord(const std::vector<std::string>& args, const fs::path& json,
                                        const fs::path& err, const std::function<void()>& edit) {
  const pid_t pid = spawnSnell(args, err.string());
  fs::path partial = json;
  partial += ".partial";
  EditedRun run;
  bool exited = false;
  for (int k = 0; k < 30000 && !exited && lineCount(partial) < 1; ++k) {
    exited = waitpid(pid, &run.status, WNOHANG) == pid;
    if (!exited) std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  run.recordsBeforeEdit = lineCount(partial);
  edit();
  if (!exited) waitpid(pid, &run.status, 0);
  return run;
}

// A listing edited while a run is in progress: a case that ends after the
// edit may have compiled either text. Its record says so in place of a
// digest, with a note, and a merge of it is refused.
TEST(BaselineCli, AListingEditedDuringTheRunIsRecordedAsSuch) {
  Scratch scratch;
  const fs::path shaders = fresnelCatalogIn(scratch);
  const fs::path json = scratch / "r.jsonl";
  const fs::path err = scratch / "err.txt";
  // One worker, four cases one after another, each computing its oracle
  // (no cache): the listing is edited as soon as the first has ended.
  const EditedRun run = runEditingAfterTheFirstRecord(
      {"run", "--backend", "gl", "-j", "1", "--oracle-cache", "off", "--shaders", shaders.string(),
       "--out", (scratch / "out").string(), "--json", json.string()},
      json, err,
      [&] { std::ofstream(shaders / "fresnel" / "fresnel.vert", std::ios::app) << "// edited\n"; });
  const std::size_t before = run.recordsBeforeEdit;
  ASSERT_GE(before, 1u) << readText(err);
  ASSERT_TRUE(WIFEXITED(run.status));
  EXPECT_EQ(WEXITSTATUS(run.status), 0) << readText(err);
  // One worker: the records are in the order the cases ended. Those that
  // ended before the edit carry the digest of the text (at least the
  // first); those after it say they cannot, and at least the last one
  // ended after it (each case computes its oracle: the three after the
  // first take far longer than the edit).
  const auto finished = records(json);
  ASSERT_EQ(finished.size(), 4u);
  std::size_t edited = 0;
  while (edited < finished.size() && finished[edited]["listing_digest"] != "edited during the run")
    ++edited;
  EXPECT_GE(edited, before);
  EXPECT_LT(edited, finished.size()) << "no case ended after the edit";
  for (std::size_t k = 0; k < finished.size(); ++k) {
    if (k < edited)
      EXPECT_EQ(finished[k]["listing_digest"].get<std::string>().size(), 32u) << k;
    else
      EXPECT_EQ(finished[k]["listing_digest"], "edited during the run") << k;
  }
  const std::string note = readText(err);
  EXPECT_NE(note.find("was edited while this run was in progress"), std::string::npos) << note;
  // Its first case ran the text before the edit, and the merge refuses it
  // for that; a shard of only the later cases is refused for what they say.
  const Outcome merged = snell(fmt::format("merge {} --shaders {} --json {}", json.string(),
                                           shaders.string(), (scratch / "m.jsonl").string()));
  EXPECT_EQ(merged.code, 2) << merged.out;
  EXPECT_NE(merged.out.find("from another text of its listing"), std::string::npos) << merged.out;
  std::ofstream(scratch / "later.jsonl") << finished.back().dump() << "\n";
  const Outcome later =
      snell(fmt::format("merge {} --shaders {} --json {}", (scratch / "later.jsonl").string(),
                        shaders.string(), (scratch / "m.jsonl").string()));
  EXPECT_EQ(later.code, 2) << later.out;
  EXPECT_NE(later.out.find("so which text it ran is unknown: run that shard again"),
            std::string::npos)
      << later.out;
}

// A failure rerun after its listing was edited (here: mended) is no flake
// of the text that failed: its record says the text is unknown.
TEST(BaselineCli, ARerunAfterAnEditDuringTheRunIsNoFlake) {
  Scratch scratch;
  const fs::path shaders = fresnelCatalogIn(scratch);
  const fs::path vert = shaders / "fresnel" / "fresnel.vert";
  const std::string published = readText(vert);
  std::string broken = published;
  ASSERT_NE(broken.find("Eta = 0.66"), std::string::npos);
  broken.replace(broken.find("Eta = 0.66"), 10, "Eta = 0.67");
  std::ofstream(vert) << broken;
  const fs::path json = scratch / "r.jsonl";
  const fs::path err = scratch / "err.txt";
  const EditedRun run = runEditingAfterTheFirstRecord(
      {"run", "--backend", "gl", "-j", "1", "--reruns", "1", "--filter", "*/sphere", "--shaders",
       shaders.string(), "--out", (scratch / "out").string(), "--json", json.string()},
      json, err, [&] { std::ofstream(vert) << published; });
  ASSERT_TRUE(WIFEXITED(run.status));
  EXPECT_EQ(WEXITSTATUS(run.status), 1) << readText(err);
  const auto finished = records(json);
  ASSERT_EQ(finished.size(), 1u);
  EXPECT_EQ(finished[0]["status"], "Fail") << readText(err);
  EXPECT_EQ(finished[0]["listing_digest"], "edited during the run") << readText(err);
  EXPECT_NE(readText(err).find("is not counted: its listing was edited during the run"),
            std::string::npos)
      << readText(err);
}

// Listing 14.1's sphere, sweep and torus cases (and the endless listing's
// sweep), leaving out the stretched scene's.
constexpr const char* kThreeFresnelCases = "*/[st][pwo]*";

// SIGTERM in the middle of a run: the workers stop, what finished is
// written and marked incomplete, exit 130; --resume runs only the rest.
TEST(BaselineCli, InterruptedRunWritesWhatFinishedAndResumes) {
  Scratch scratch;
  const fs::path shaders = fresnelCatalogIn(scratch);
  fs::copy(SNELL_SOURCE_ROOT "/tests/faults/endless-loop", shaders / "endless-loop");
  const fs::path json = scratch / "r.jsonl";
  // Two workers: one hangs in the endless listing, the other finishes the
  // three Fresnel cases.
  const pid_t pid = spawnSnell({"run", "--backend", "gl", "-j", "2", "--timeout", "60", "--reruns",
                                "0", "--filter", kThreeFresnelCases, "--shaders", shaders.string(),
                                "--out", (scratch / "out").string(), "--json", json.string(),
                                "--junit", (scratch / "r.xml").string()});
  fs::path partial = json;
  partial += ".partial";
  for (int k = 0; k < 600 && lineCount(partial) < 3; ++k)
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  ASSERT_EQ(lineCount(partial), 3u);
  kill(pid, SIGTERM);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 130);
  const auto finished = records(json);
  ASSERT_EQ(finished.size(), 3u);
  for (const auto& r : finished) {
    EXPECT_EQ(r["status"], "Pass") << r["case"];
    EXPECT_EQ(r["incomplete"], true);
  }
  EXPECT_NE(readText(scratch / "r.xml").find("incomplete: interrupted by SIGTERM after 3 of 4"),
            std::string::npos)
      << readText(scratch / "r.xml");

  // Merged, the records stay marked: the merge of an interrupted run is
  // no complete run, and a gate on it does not pass (exit 1, naming it).
  const Outcome merged = snell(
      fmt::format("merge {} --shaders {} --json {} --junit {}", json.string(), shaders.string(),
                  (scratch / "merged.jsonl").string(), (scratch / "merged.xml").string()));
  EXPECT_EQ(merged.code, 1) << merged.out;
  EXPECT_NE(merged.out.find("snell: merged from a shard that was interrupted (" + json.string() +
                            "): its cases not reached are missing; the merged results are "
                            "marked incomplete"),
            std::string::npos)
      << merged.out;
  EXPECT_NE(merged.out.find("is an interrupted run"), std::string::npos) << merged.out;
  const auto mergedRecords = records(scratch / "merged.jsonl");
  ASSERT_EQ(mergedRecords.size(), 3u);
  for (const auto& r : mergedRecords) EXPECT_EQ(r["incomplete"], true) << r["case"];
  EXPECT_NE(readText(scratch / "merged.xml").find("merged from a shard that was interrupted"),
            std::string::npos)
      << readText(scratch / "merged.xml");

  // The endless case alone runs on resume, with a short limit.
  const Outcome resumed = snell(fmt::format(
      "run --backend gl --timeout 1 --reruns 0 --filter '{}' --shaders {} --out {} --resume {} "
      "--json {}",
      kThreeFresnelCases, shaders.string(), (scratch / "out").string(), json.string(),
      (scratch / "all.jsonl").string()));
  EXPECT_EQ(resumed.code, 1) << resumed.out;
  EXPECT_NE(resumed.out.find("[4/4] gl faults/endless-loop/sweep Timeout"), std::string::npos)
      << resumed.out;
  EXPECT_EQ(resumed.out.find("[1/4]"), std::string::npos) << resumed.out;
  const auto all = records(scratch / "all.jsonl");
  ASSERT_EQ(all.size(), 4u);
  for (const auto& r : all) EXPECT_FALSE(r.contains("incomplete"));

  const std::string rest =
      fmt::format("run --backend gl --timeout 1 --reruns 0 --filter '{}' --shaders {} --out {}",
                  kThreeFresnelCases, shaders.string(), (scratch / "out").string());
  // A finished run has nothing to go on with: resuming it would copy it,
  // stale, over --json.
  const Outcome finishedAgain =
      snell(fmt::format("{} --resume {} --json {}", rest, (scratch / "all.jsonl").string(),
                        (scratch / "again.jsonl").string()));
  EXPECT_EQ(finishedAgain.code, 2) << finishedAgain.out;
  EXPECT_NE(finishedAgain.out.find("a finished run (4 records, none marked incomplete)"),
            std::string::npos)
      << finishedAgain.out;
  EXPECT_FALSE(fs::exists(scratch / "again.jsonl"));
  // A FILE.partial that a killed run left is the only copy of its cases: a
  // run that would write over it is refused, and resuming it goes on.
  const fs::path killed = scratch / "killed.jsonl";
  const std::string killedText = readText(json);
  std::ofstream(fs::path(killed.string() + ".partial")) << killedText;
  const Outcome over = snell(fmt::format("{} --json {}", rest, killed.string()));
  EXPECT_EQ(over.code, 2) << over.out;
  EXPECT_NE(over.out.find("holds the results of a run that was killed: go on with it (--resume "),
            std::string::npos)
      << over.out;
  EXPECT_EQ(readText(killed.string() + ".partial"), killedText);
  const Outcome goesOn = snell(
      fmt::format("{} --resume {}.partial --json {}", rest, killed.string(), killed.string()));
  EXPECT_EQ(goesOn.code, 1) << goesOn.out;  // the endless case times out
  EXPECT_EQ(records(killed).size(), 4u);
  // An empty one (killed before its first result) has nothing to lose: the
  // run goes ahead.
  const fs::path empty = scratch / "empty.jsonl";
  std::ofstream(fs::path(empty.string() + ".partial")).flush();
  const Outcome overEmpty = snell(fmt::format("{} --json {}", rest, empty.string()));
  EXPECT_EQ(overEmpty.out.find("holds the results of a run that was killed"), std::string::npos)
      << overEmpty.out;
  EXPECT_EQ(records(empty).size(), 4u);
}

// What a run or report writes is checked before the work: --junit in a
// folder where no file can be made (/proc, which root's access() calls
// writable) was refused only after every case had run; a report would
// write its page over the results file it was reading; and a run stopped
// before its first result, which says to go on with --resume, was refused
// as "a finished run".
TEST(BaselineCli, OutputsAreCheckedBeforeTheWorkAndAnEmptyRunCanBeResumed) {
  Scratch scratch;
  const std::string one = "--backend gl --filter 'orange-book/14.1-fresnel/sweep'";
  const Outcome junit = snell(fmt::format("run {} --out {} --junit /proc/snell-junit.xml", one,
                                          (scratch / "out").string()));
  EXPECT_EQ(junit.code, 2) << junit.out;
  // To root, access() calls /proc writable and the file made there fails;
  // to anyone else access() says no first.
  EXPECT_NE(
      junit.out.find(::geteuid() == 0
                         ? "--junit /proc/snell-junit.xml: no file can be made in folder /proc"
                         : "--junit /proc/snell-junit.xml: folder /proc is not writable"),
      std::string::npos)
      << junit.out;
  EXPECT_EQ(junit.out.find("Pass"), std::string::npos) << "ran before refusing: " << junit.out;

  const fs::path empty = scratch / "stopped.jsonl";
  std::ofstream(empty).close();
  const Outcome resumed =
      snell(fmt::format("run {} --out {} --json {} --resume {}", one, (scratch / "out").string(),
                        empty.string(), empty.string()));
  EXPECT_EQ(resumed.code, 0) << resumed.out;
  EXPECT_EQ(records(empty).size(), 1u);

  fs::create_directories(scratch / "page");
  const fs::path page = scratch / "page" / "index.html";
  fs::copy_file(empty, page);
  const std::string before = readText(page);
  const Outcome report =
      snell(fmt::format("report {} -o {}", page.string(), (scratch / "page").string()));
  EXPECT_EQ(report.code, 2) << report.out;
  EXPECT_NE(report.out.find("is the page this report would write"), std::string::npos)
      << report.out;
  EXPECT_EQ(readText(page), before) << "the results file was written over";
}

// --resume goes on with the run that wrote the file: results of another
// driver build under the same backend, or of cases this command does not
// run (another --filter), were kept or dropped without a word.
TEST(BaselineCli, ResumeRefusesAnotherDriverBuildAndAnotherCommandsResults) {
  Scratch scratch;
  const std::string one = "--backend gl --filter 'orange-book/14.1-fresnel/sweep'";
  const fs::path full = scratch / "full.jsonl";
  ASSERT_EQ(snell(fmt::format("run {} --out {} --json {}", one, (scratch / "out").string(),
                              full.string()))
                .code,
            0);
  const auto interrupted = [&](const std::string& name, auto&& edit) {
    std::vector<nlohmann::json> lines = records(full);
    std::ofstream file(scratch / name);
    for (nlohmann::json& line : lines) {
      line["incomplete"] = true;
      edit(line);
      file << line.dump() << "\n";
    }
    return (scratch / name).string();
  };
  const std::string newer = interrupted(
      "newer.jsonl", [](nlohmann::json& line) { line["driver"]["driver_version"] = "Mesa 99.0"; });
  const Outcome driver =
      snell(fmt::format("run {} --out {} --json {} --resume {}", one, (scratch / "out").string(),
                        (scratch / "r1.jsonl").string(), newer));
  EXPECT_EQ(driver.code, 2) << driver.out;
  EXPECT_NE(driver.out.find("its gl results ran on Mesa 99.0"), std::string::npos) << driver.out;

  const std::string same = interrupted("same.jsonl", [](nlohmann::json&) {});
  const Outcome other = snell(fmt::format(
      "run --backend gl --filter 'orange-book/14.1-fresnel/sphere' --out {} --json {} --resume {}",
      (scratch / "out").string(), (scratch / "r2.jsonl").string(), same));
  EXPECT_EQ(other.code, 2) << other.out;
  EXPECT_NE(other.out.find("holds 1 result this command does not give (one: "
                           "orange-book/14.1-fresnel/sweep on gl)"),
            std::string::npos)
      << other.out;
  EXPECT_FALSE(fs::exists(scratch / "r2.jsonl"));

  const Outcome goesOn =
      snell(fmt::format("run {} --out {} --json {} --resume {}", one, (scratch / "out").string(),
                        (scratch / "r3.jsonl").string(), same));
  EXPECT_EQ(goesOn.code, 0) << goesOn.out;
}

}  // namespace
