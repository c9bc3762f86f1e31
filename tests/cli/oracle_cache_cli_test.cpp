// `run --oracle-cache`: a second run reads the oracle results the first one
// computed and says so (for Listing 14.1 on three scenes: three vector
// results and the sphere's reference image); `off` keeps none; a folder
// that cannot be made is said once and costs only speed.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "snell_process.h"

namespace {

namespace fs = std::filesystem;
using snell::testing::runSnell;

class OracleCacheCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / fmt::format("snell-oracle-cache-cli-{}", getpid());
    fs::remove_all(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  snell::testing::Outcome run(const std::string& cache) {
    return runSnell(
        fmt::format("run --backend gl --filter 'orange-book/14.1-fresnel/s*' "
                    "--out {} --oracle-cache {}",
                    (dir_ / "out").string(), cache));
  }
  fs::path dir_;
};

TEST_F(OracleCacheCli, ASecondRunReadsWhatTheFirstComputed) {
  const std::string store = (dir_ / "store").string();
  const auto first = run(store);
  ASSERT_EQ(first.code, 0) << first.out;
  EXPECT_NE(first.out.find(fmt::format("oracle results: 4 computed, 0 read from {}", store)),
            std::string::npos)
      << first.out;
  const auto second = run(store);
  ASSERT_EQ(second.code, 0) << second.out;
  EXPECT_NE(second.out.find(fmt::format("oracle results: 0 computed, 4 read from {}", store)),
            std::string::npos)
      << second.out;
}

TEST_F(OracleCacheCli, OffKeepsNone) {
  const auto outcome = run("off");
  ASSERT_EQ(outcome.code, 0) << outcome.out;
  EXPECT_NE(outcome.out.find("oracle results: 4 computed, none kept (no oracle cache this run)"),
            std::string::npos)
      << outcome.out;
}

TEST_F(OracleCacheCli, AFolderThatCannotBeMadeIsSaidAndTheRunGoesOn) {
  fs::create_directories(dir_);
  std::ofstream(dir_ / "file") << "not a folder";
  const auto outcome = run((dir_ / "file" / "store").string());
  ASSERT_EQ(outcome.code, 0) << outcome.out;
  EXPECT_NE(outcome.out.find("cannot keep oracle results or compiled programs here"),
            std::string::npos)
      << outcome.out;
  EXPECT_NE(outcome.out.find("none kept"), std::string::npos) << outcome.out;
}

// CI runs into a fresh --out every time: the store keeps what such a run
// computes once, and the next one adds nothing (the decoded images it keeps
// are keyed by the image files' bytes, which are the pixels alone).
TEST_F(OracleCacheCli, RunsIntoFreshOutFoldersKeepNothingNew) {
  const std::string store = (dir_ / "store").string();
  const auto entries = [&] {
    std::size_t n = 0;
    for (const auto& e : fs::recursive_directory_iterator(store))
      if (e.path().extension() == ".result") ++n;
    return n;
  };
  std::vector<std::size_t> counts;
  for (const char* out : {"out1", "out2", "out3"}) {
    const auto outcome = runSnell(fmt::format(
        "run --backend gl,vk --filter 'orange-book/14.1-fresnel/sphere' --out {} --oracle-cache {}",
        (dir_ / out).string(), store));
    ASSERT_EQ(outcome.code, 0) << outcome.out;
    counts.push_back(entries());
  }
  EXPECT_EQ(counts[1], counts[0]) << "the second run kept new entries";
  EXPECT_EQ(counts[2], counts[0]) << "the third run kept new entries";
}

// A run on the same driver as the one before needs no image module at all:
// its pictures, comparisons and decoded images are what that run kept. The
// module is replaced by a file of the same name, size and time that cannot
// be opened (so the stored results stay keyed to it): the kept run passes
// as before, and one that keeps nothing cannot compare an image.
TEST_F(OracleCacheCli, ARunAgainOpensNoImageModule) {
  fs::create_directories(dir_);
  const fs::path module = dir_ / "libsnell_image_library.so";
  fs::copy_file(SNELL_IMAGE_LIBRARY_PATH, module);
  const auto time = fs::last_write_time(module);
  const std::string env = fmt::format("SNELL_IMAGE_LIBRARY={}", module.string());
  const std::string store = (dir_ / "store").string();
  const std::string args = fmt::format(
      "run --backend gl,vk --filter 'orange-book/14.1-fresnel/sphere' --out {} --json {} ",
      (dir_ / "out").string(), (dir_ / "results.jsonl").string());
  const auto first = runSnell(args + "--oracle-cache " + store, env);
  ASSERT_EQ(first.code, 0) << first.out;
  const std::uintmax_t size = fs::file_size(module);
  std::ofstream(module, std::ios::binary | std::ios::trunc) << std::string(size, '\0');
  fs::last_write_time(module, time);
  const auto again = runSnell(args + "--oracle-cache " + store, env);
  EXPECT_EQ(again.code, 0) << again.out;
  EXPECT_NE(again.out.find("2 Pass"), std::string::npos) << again.out;
  EXPECT_NE(again.out.find("0 computed"), std::string::npos) << again.out;
  const auto without = runSnell(args + "--oracle-cache off", env);
  EXPECT_NE(without.code, 0) << "the replaced module really cannot be opened:\n" << without.out;
  EXPECT_NE(without.out.find("libsnell_image_library.so"), std::string::npos) << without.out;
}

}  // namespace

namespace {

// The files under `dir` that hold a compiled Vulkan program (their header
// names the store).
int compiledPrograms(const fs::path& dir) {
  int n = 0;
  if (!fs::exists(dir)) return 0;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    if (!entry.is_regular_file()) continue;
    std::ifstream in(entry.path(), std::ios::binary);
    char magic[8] = {};
    in.read(magic, sizeof magic);
    n += std::string(magic, sizeof magic) == "snellspv";
  }
  return n;
}

}  // namespace

// `eval` on vk keeps its compiled probe programs where runs keep oracle
// results ($SNELL_ORACLE_CACHE), and answers the same when it reads them.
TEST_F(OracleCacheCli, EvalOnVkKeepsItsCompiledPrograms) {
  fs::create_directories(dir_);
  const fs::path input = dir_ / "input.jsonl";
  std::ofstream(input) << R"({"fn":"refract","I":[0.6,-0.8,0],"N":[0,1,0],"eta":0.66})"
                       << "\n"
                       << R"({"fn":"reflect","I":[0.6,-0.8],"N":[0,1]})"
                       << "\n";
  const std::string env = fmt::format("SNELL_ORACLE_CACHE={}", (dir_ / "store").string());
  const auto first = runSnell("eval --backend vk " + input.string(), env);
  ASSERT_EQ(first.code, 0) << first.out;
  EXPECT_EQ(compiledPrograms(dir_ / "store"), 2);
  const auto second = runSnell("eval --backend vk " + input.string(), env);
  ASSERT_EQ(second.code, 0) << second.out;
  EXPECT_EQ(second.out, first.out);
  EXPECT_EQ(compiledPrograms(dir_ / "store"), 2);
  const auto off = runSnell("eval --backend vk " + input.string(), "SNELL_ORACLE_CACHE=off");
  EXPECT_EQ(off.out, first.out);
}

// SNELL_ORACLE_CACHE that is no folder to keep programs in is said, as
// run says it for --oracle-cache, and the answers are the same; OFF in
// capitals is off too, not a folder of that name.
TEST_F(OracleCacheCli, EvalSaysWhenItsStoreCannotBeKept) {
  fs::create_directories(dir_);
  const fs::path input = dir_ / "input.jsonl";
  std::ofstream(input) << R"({"fn":"reflect","I":[0.6,-0.8],"N":[0,1]})"
                       << "\n";
  std::ofstream(dir_ / "file") << "not a folder";
  const auto kept = runSnell("eval --backend vk " + input.string(),
                             fmt::format("SNELL_ORACLE_CACHE={}", (dir_ / "store").string()));
  ASSERT_EQ(kept.code, 0) << kept.out;
  const auto onAFile = runSnell("eval --backend vk " + input.string(),
                                fmt::format("SNELL_ORACLE_CACHE={}", (dir_ / "file").string()));
  EXPECT_EQ(onAFile.code, 0) << onAFile.out;
  EXPECT_NE(onAFile.out.find((dir_ / "file").string() +
                             ": cannot keep oracle results or compiled programs here (not a "
                             "folder)"),
            std::string::npos)
      << onAFile.out;
  EXPECT_NE(onAFile.out.find(kept.out), std::string::npos) << onAFile.out;
  const auto capitals = runSnell("eval --backend vk " + input.string(),
                                 fmt::format("cd {} && SNELL_ORACLE_CACHE=OFF", dir_.string()));
  EXPECT_EQ(capitals.code, 0) << capitals.out;
  EXPECT_FALSE(fs::exists(dir_ / "OFF"));
}

// `run`'s vk workers keep their compiled programs in `--oracle-cache`, and
// `off` keeps none.
TEST_F(OracleCacheCli, RunOnVkKeepsItsCompiledPrograms) {
  const std::string args = fmt::format(
      "run --backend vk --filter 'orange-book/14.1-fresnel/sphere' --out {} --oracle-cache ",
      (dir_ / "out").string());
  const auto kept = runSnell(args + (dir_ / "store").string());
  ASSERT_EQ(kept.code, 0) << kept.out;
  EXPECT_GE(compiledPrograms(dir_ / "store"), 1);
  const auto off =
      runSnell(args + "off", fmt::format("SNELL_ORACLE_CACHE={}", (dir_ / "env").string()));
  ASSERT_EQ(off.code, 0) << off.out;
  EXPECT_EQ(compiledPrograms(dir_ / "env"), 0);
}
