// `snell bench` on the dispersion and refraction ladders as a user runs
// it, on a tiny image: a record per method and backend, the charts, and the
// order physics gives. Timing is never asserted.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <thread>

#include "../cli/snell_process.h"
#include "bench/bench_record.h"
#include "bench/ladder_checks.h"

namespace snell::testing {
namespace {

namespace fs = std::filesystem;

class DispersionBenchCli : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = fs::temp_directory_path() / fmt::format("snell_dispersion_bench_test.{}", getpid());
    fs::remove_all(dir_);
    run_ = new Outcome(runSnell(fmt::format(
        "bench --methods {}/shaders/methods/dispersion --resolutions 48 --repeats 1 --warmup 0 "
        "--reference-wavelengths 64 --out {}",
        SNELL_SOURCE_ROOT, dir_.string())));
  }
  static void TearDownTestSuite() {
    delete run_;
    fs::remove_all(dir_);
  }
  static bench::BenchResults results() { return bench::readBenchResults(dir_ / "bench.json"); }
  static inline fs::path dir_;
  static inline Outcome* run_ = nullptr;
};

TEST_F(DispersionBenchCli, WritesEveryMethodOnEveryBackendAndTheWavelengthChart) {
  ASSERT_EQ(run_->code, 0) << run_->out;
  const bench::BenchResults r = results();
  EXPECT_NE(r.reference.find("N-BK7, 64 wavelengths"), std::string::npos) << r.reference;
  EXPECT_EQ(r.records.size(), 12u);
  for (const bench::BenchRecord& record : r.records)
    EXPECT_FALSE(record.parameters.empty()) << record.method;
  EXPECT_GT(fs::file_size(dir_ / "wavelengths.svg"), 1000u);
  EXPECT_GT(fs::file_size(dir_ / "wavelengths.png"), 1000u);
}

// Physics: more wavelengths never move away from the reference beyond the
// noise, and the book's exaggerated, reversed indices are the farthest.
TEST_F(DispersionBenchCli, MoreWavelengthsNeverMoveAwayAndTheBookIsFarthest) {
  ASSERT_EQ(run_->code, 0) << run_->out;
  const bench::BenchResults r = results();
  for (const std::string metric : {"rms", "de_mean", "de_p95"}) {
    const auto violations = bench::wavelengthOrderViolations(r, metric, bench::errorNoise(metric));
    EXPECT_TRUE(violations.empty()) << metric << ": " << violations.front();
    for (const char* backend : {"gl", "vk"}) {
      std::string worst;
      double worstError = -1;
      for (const bench::BenchRecord& record : r.records)
        if (record.backend == backend && bench::errorMetric(record.error, metric) > worstError)
          worstError = bench::errorMetric(record.error, metric), worst = record.method;
      EXPECT_EQ(worst, "methods/dispersion/1-rgb-book-etas") << metric << " on " << backend;
    }
  }
}

// The refraction ladder: each interface and internal reflection a method
// follows brings it nearer the traced sphere, on every backend and metric.
TEST(RefractionBenchCli, EachModelledInterfaceBringsAMethodNearer) {
  const fs::path dir =
      fs::temp_directory_path() / fmt::format("snell_refraction_bench_test.{}", getpid());
  fs::remove_all(dir);
  const Outcome run = runSnell(fmt::format(
      "bench --methods {}/shaders/methods/refraction --resolutions 48 --repeats 1 --warmup 0 "
      "--no-ablation --out {}",
      SNELL_SOURCE_ROOT, dir.string()));
  ASSERT_EQ(run.code, 0) << run.out;
  const bench::BenchResults r = bench::readBenchResults(dir / "bench.json");
  fs::remove_all(dir);
  EXPECT_NE(r.reference.find("8 hits from inside"), std::string::npos) << r.reference;
  ASSERT_EQ(r.records.size(), 6u);
  const std::vector<std::string> ladder{"methods/refraction/1-one-interface",
                                        "methods/refraction/2-two-interfaces",
                                        "methods/refraction/3-internal-bounces"};
  for (const std::string metric : {"rms", "de_mean", "de_p95"})
    for (const char* backend : {"gl", "vk"}) {
      std::vector<double> errors;
      for (const std::string& method : ladder)
        for (const bench::BenchRecord& record : r.records)
          if (record.backend == backend && record.method == method)
            errors.push_back(bench::errorMetric(record.error, metric));
      ASSERT_EQ(errors.size(), 3u) << backend;
      EXPECT_GT(errors[0], errors[1]) << metric << " on " << backend;
      EXPECT_GT(errors[1], errors[2]) << metric << " on " << backend;
    }
}

}  // namespace
// One ladder benched without --out goes where `advise --ladder` reads it
// (snell-bench/LADDER/bench.json): it went to snell-bench/bench.json, and
// advise then said to run `snell bench` first.
TEST(LadderBenchCli, OneLadderWithoutOutIsWhereAdviseReadsIt) {
  const fs::path cwd = fs::temp_directory_path() / fmt::format("snell_bench_cwd.{}", getpid());
  fs::remove_all(cwd);
  fs::create_directories(cwd);
  const std::string here = fmt::format("cd {} &&", cwd.string());
  const Outcome bench =
      runSnell(fmt::format("bench --methods {}/shaders/methods/fresnel/ --backends vk "
                           "--resolutions 16 --tessellations 6 --repeats 1 --warmup 0 "
                           "--no-ablation",
                           SNELL_SOURCE_ROOT),
               here);
  ASSERT_EQ(bench.code, 0) << bench.out;
  EXPECT_TRUE(fs::exists(cwd / "snell-bench" / "fresnel" / "bench.json"));
  const Outcome advise = runSnell("advise --scene sphere --budget 1000", here);
  EXPECT_EQ(advise.code, 0) << advise.out;
  fs::remove_all(cwd);
}

// A method that does not compile stops the bench before any method is
// timed: it stopped it after minutes of timing the ones before it, which
// were then lost.
TEST(LadderBenchCli, AMethodThatDoesNotCompileStopsTheBenchBeforeAnyTiming) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("snell_broken_ladder.{}", getpid());
  fs::remove_all(dir);
  fs::create_directories(dir);
  fs::copy(fs::path(SNELL_SOURCE_ROOT) / "shaders/methods/fresnel", dir / "fresnel",
           fs::copy_options::recursive);
  std::ofstream(dir / "fresnel/6-exact-fragment/exact.frag", std::ios::app) << "\nnot glsl;\n";
  const Outcome run = runSnell(
      fmt::format("bench --methods {} --backends gl --resolutions 16 --tessellations 6 --repeats 1 "
                  "--warmup 0 --no-ablation --out {}",
                  (dir / "fresnel").string(), (dir / "out").string()));
  EXPECT_EQ(run.code, 2) << run.out;
  EXPECT_NE(run.out.find("exact.frag"), std::string::npos) << run.out;
  EXPECT_EQ(run.out.find("ms per frame"), std::string::npos)
      << "timed before refusing: " << run.out;
  fs::remove_all(dir);
}

// A folder of ladders whose later ladder has a method the physics
// reference refuses is refused before the earlier ladder is timed: it was
// found only after minutes of timing the ladders before it.
TEST(LadderBenchCli, ALaterLaddersMistakeIsFoundBeforeAnyLadderIsTimed) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("snell_later_ladder.{}", getpid());
  fs::remove_all(dir);
  fs::create_directories(dir / "ladders");
  for (const char* name : {"a-fresnel", "b-fresnel"})
    fs::copy(fs::path(SNELL_SOURCE_ROOT) / "shaders/methods/fresnel", dir / "ladders" / name,
             fs::copy_options::recursive);
  const fs::path wrong = dir / "ladders/b-fresnel/2-empirical/manifest.toml";
  std::string manifest = readText(wrong);
  const std::size_t eta = manifest.find("Eta = 0.6666667");
  ASSERT_NE(eta, std::string::npos) << manifest;
  std::ofstream(wrong) << manifest.replace(eta, 15, "Eta = 1.5");
  const Outcome run = runSnell(
      fmt::format("bench --methods {} --backends gl --resolutions 16 --tessellations 6 --repeats 1 "
                  "--warmup 0 --no-ablation --out {}",
                  (dir / "ladders").string(), (dir / "out").string()));
  EXPECT_EQ(run.code, 2) << run.out;
  EXPECT_NE(run.out.find(wrong.string() + ":1: Eta 1.5 is not n1/n2"), std::string::npos)
      << run.out;
  EXPECT_EQ(run.out.find("ms per frame"), std::string::npos)
      << "timed before refusing: " << run.out;
  EXPECT_FALSE(fs::exists(dir / "out" / "a-fresnel" / "bench.json"));
  fs::remove_all(dir);
}

// One method's folder given as --methods said "no method manifests found
// here" beside its manifest.toml.
TEST(LadderBenchCli, OneMethodsFolderIsNamedAsNotALadder) {
  const Outcome run = runSnell(
      fmt::format("bench --methods {}/shaders/methods/fresnel/1-constant-mix --backends gl "
                  "--no-ablation --out /tmp/snell-bench-one-method",
                  SNELL_SOURCE_ROOT));
  EXPECT_EQ(run.code, 2) << run.out;
  EXPECT_NE(run.out.find("1-constant-mix: one method (its manifest.toml), not a ladder of "
                         "methods; give --methods the folder that holds it"),
            std::string::npos)
      << run.out;
  EXPECT_FALSE(fs::exists("/tmp/snell-bench-one-method"));
}

// A file where a ladder's images or bench.json go was found after the
// ladder's measurement, as an internal error.
TEST(LadderBenchCli, AFileWhereALaddersOutputsGoIsRefusedBeforeAnyTiming) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("snell_bench_file.{}", getpid());
  for (const char* blocked : {"images", "bench.json/"}) {
    fs::remove_all(dir);
    fs::create_directories(dir / "out");
    if (std::string(blocked).ends_with("/"))
      fs::create_directories(dir / "out" / blocked);  // a folder where the file goes
    else
      std::ofstream(dir / "out" / blocked) << "mine";
    const Outcome run = runSnell(
        fmt::format("bench --methods {}/shaders/methods/fresnel --backends gl --resolutions 16 "
                    "--tessellations 6 --repeats 1 --warmup 0 --no-ablation --out {}",
                    SNELL_SOURCE_ROOT, (dir / "out").string()));
    EXPECT_EQ(run.code, 2) << blocked << ": " << run.out;
    EXPECT_NE(run.out.find((dir / "out").string()), std::string::npos) << run.out;
    EXPECT_EQ(run.out.find("internal error"), std::string::npos) << run.out;
    EXPECT_EQ(run.out.find("ms per frame"), std::string::npos)
        << "timed before refusing: " << run.out;
  }
  fs::remove_all(dir);
}

// A bench into the folder of an earlier one left that one's gl images,
// chart data and vertex chart beside a bench.json of vk alone: they are
// replaced, and files the bench never writes are left (it removed every
// *.dat and every image it had not written, a user's among them).
TEST(LadderBenchCli, AnEarlierBenchsOutputsDoNotStayBesideANewOnesResults) {
  const fs::path out = fs::temp_directory_path() / fmt::format("snell_bench_again.{}", getpid());
  fs::remove_all(out);
  const auto bench = [&](const char* backends, const char* tessellations) {
    return runSnell(
        fmt::format("bench --methods {}/shaders/methods/fresnel --backends {} --resolutions 16 "
                    "--tessellations {} --repeats 1 --warmup 0 --no-ablation --out {}",
                    SNELL_SOURCE_ROOT, backends, tessellations, out.string()));
  };
  ASSERT_EQ(bench("gl,vk", "6,12").code, 0);
  ASSERT_TRUE(fs::exists(out / "vertices.png"));
  ASSERT_TRUE(fs::exists(out / "front_gl.dat"));
  // Files of the user's, in names the bench does not write.
  std::ofstream(out / "notes.txt") << "mine";
  std::ofstream(out / "measurements.dat") << "mine";
  std::ofstream(out / "images" / "photo.exr") << "mine";
  ASSERT_EQ(bench("vk", "6").code, 0);
  EXPECT_FALSE(fs::exists(out / "vertices.png")) << "one tessellation draws no vertex chart";
  EXPECT_FALSE(fs::exists(out / "front_gl.dat"));
  EXPECT_TRUE(fs::exists(out / "front_vk.dat"));
  for (const auto& entry : fs::directory_iterator(out / "images"))
    EXPECT_EQ(entry.path().filename().string().find(".gl."), std::string::npos) << entry.path();
  EXPECT_TRUE(fs::exists(out / "images" / "physics_reference.exr"));
  EXPECT_TRUE(fs::exists(out / "notes.txt"));
  EXPECT_TRUE(fs::exists(out / "measurements.dat"));
  EXPECT_TRUE(fs::exists(out / "images" / "photo.exr"));
  fs::remove_all(out);
}

// Ctrl-C on a bench into the folder of an earlier one wrote the images of
// the methods it had measured over that one's, beside the earlier
// bench.json they no longer matched (and said none was written): the new
// images go into images/ only with the new bench.json.
TEST(LadderBenchCli, AnInterruptedBenchLeavesTheEarlierOnesImages) {
  const fs::path out = fs::temp_directory_path() / fmt::format("snell_bench_int.{}", getpid());
  fs::remove_all(out);
  const std::string methods = std::string(SNELL_SOURCE_ROOT) + "/shaders/methods/fresnel";
  ASSERT_EQ(runSnell(fmt::format("bench --methods {} --backends gl --resolutions 16 "
                                 "--tessellations 6 --repeats 1 --warmup 0 --no-ablation --out {}",
                                 methods, out.string()))
                .code,
            0);
  const auto contents = [&] {
    std::map<std::string, std::string> files;
    for (const auto& entry : fs::recursive_directory_iterator(out))
      files[fs::relative(entry.path(), out).string()] =
          entry.is_regular_file() ? readText(entry.path()) : "(folder)";
    return files;
  };
  const std::map<std::string, std::string> before = contents();
  ASSERT_TRUE(before.count("images/physics_reference.exr"));
  const fs::path err = out.string() + ".err";
  const pid_t pid = spawnSnell({"bench", "--methods", methods, "--backends", "gl", "--resolutions",
                                "32,128", "--tessellations", "6", "--repeats", "50", "--warmup",
                                "0", "--no-ablation", "--out", out.string()},
                               err.string());
  // A method's line comes once it is measured (and its image written).
  for (int k = 0; k < 6000 && readText(err).find(" ms per frame at ") == std::string::npos; ++k)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  ::kill(pid, SIGINT);
  int status = 0;
  ::waitpid(pid, &status, 0);
  const std::string said = readText(err);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 128 + SIGINT) << said;
  EXPECT_NE(said.find("bench interrupted by SIGINT after "), std::string::npos) << said;
  EXPECT_TRUE(contents() == before) << "the earlier run's files changed; " << said;
  fs::remove_all(out);
  fs::remove(err);
}

}  // namespace snell::testing
