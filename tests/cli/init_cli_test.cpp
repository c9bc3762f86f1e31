// `snell init DIR` as a user runs it: a manifest written, never one
// overwritten without --force, and one clear message with exit code 2 for
// bad input.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "snell_process.h"

namespace snell {
namespace {

namespace fs = std::filesystem;
using testing::readText;
using testing::runSnell;

class InitCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           fmt::format("snell-init-{}-{}", getpid(),
                       ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  void copyListing() {
    // The catalog's CS 381 listing: its own stage files, no manifest.
    const fs::path listing = SNELL_SOURCE_ROOT "/shaders/cs381/refraction";
    fs::copy_file(listing / "eyespace.vert", dir_ / "eyespace.vert");
    fs::copy_file(listing / "refraction.frag", dir_ / "refraction.frag");
  }

  fs::path dir_;
};

TEST_F(InitCli, WritesTheManifestThenRefusesToOverwriteIt) {
  copyListing();
  const auto first = runSnell("init " + dir_.string());
  EXPECT_EQ(first.code, 0) << first.out;
  const std::string written = readText(dir_ / "manifest.toml");
  EXPECT_NE(written.find("stages = { vertex = \"eyespace.vert\", fragment = \"refraction.frag\" }"),
            std::string::npos)
      << written;

  std::ofstream(dir_ / "manifest.toml") << "# mine\n";
  const auto again = runSnell("init " + dir_.string());
  EXPECT_EQ(again.code, 2);
  EXPECT_NE(again.out.find("manifest.toml exists; snell init never overwrites a manifest: pass "
                           "--force to replace it"),
            std::string::npos)
      << again.out;
  EXPECT_EQ(readText(dir_ / "manifest.toml"), "# mine\n");

  const auto forced = runSnell("init --force " + dir_.string());
  EXPECT_EQ(forced.code, 0) << forced.out;
  EXPECT_EQ(readText(dir_ / "manifest.toml"), written);
}

TEST_F(InitCli, BadInputIsOneMessageAndExit2) {
  const struct {
    std::string args, message;
  } cases[] = {
      {"init " + (dir_ / "missing").string(), "no such folder"},
      {"init " + dir_.string(), "holds no GLSL vertex stage (*.vert)"},
      {"init --vertex nope.vert " + dir_.string(), "nope.vert: no such vertex stage file"},
      {"init", "dir is required"},
  };
  for (const auto& c : cases) {
    const auto outcome = runSnell(c.args);
    EXPECT_EQ(outcome.code, 2) << c.args << "\n" << outcome.out;
    EXPECT_NE(outcome.out.find(c.message), std::string::npos) << c.args << "\n" << outcome.out;
  }
  EXPECT_FALSE(fs::exists(dir_ / "manifest.toml"));
}

TEST_F(InitCli, AStageWithoutMainIsRefused) {
  std::ofstream(dir_ / "notes.vert") << "not a shader\n";
  const auto outcome = runSnell("init " + dir_.string());
  EXPECT_EQ(outcome.code, 2) << outcome.out;
  EXPECT_NE(outcome.out.find("notes.vert: no `void main()`"), std::string::npos) << outcome.out;
  EXPECT_EQ(std::count(outcome.out.begin(), outcome.out.end(), '\n'), 1) << outcome.out;
  EXPECT_FALSE(fs::exists(dir_ / "manifest.toml"));
}

}  // namespace
}  // namespace snell

namespace snell {
namespace {

// From nothing to a passing gated case on both backends, as shaders/README.md
// walks through it: the LearnOpenGL refraction pair, `snell init`, the
// citation filled in, `snell bless` for the goldens, `snell run`. The
// vertex stage's Normal (through inverse()) is left out, saying why.
TEST(InitThenRun, ALearnOpenGLPairRunsAsDraftedOnceTheCitationIsFilledIn) {
  const fs::path root = fs::temp_directory_path() / fmt::format("snell-init-run-{}", getpid());
  fs::remove_all(root);
  const fs::path listing = root / "shaders" / "mine" / "refraction";
  fs::create_directories(listing);
  fs::create_directories(root / "golden");
  const fs::path published = SNELL_SOURCE_ROOT "/shaders/learnopengl/refraction";
  fs::copy_file(published / "cubemaps.vert", listing / "cubemaps.vert");
  fs::copy_file(published / "refraction.frag", listing / "refraction.frag");

  ASSERT_EQ(runSnell("init " + listing.string()).code, 0);
  std::string manifest = readText(listing / "manifest.toml");
  EXPECT_NE(manifest.find("# Not captured: Normal (cubemaps.vert:14: inverse() has no precision"),
            std::string::npos)
      << manifest;
  const std::string placeholder =
      R"(file = "FILL IN: the document or URL", where = "FILL IN: the listing or section")";
  ASSERT_NE(manifest.find(placeholder), std::string::npos) << manifest;
  const auto unfilled = runSnell("run --shaders " + (root / "shaders").string());
  EXPECT_EQ(unfilled.code, 2) << unfilled.out;
  manifest.replace(
      manifest.find(placeholder), placeholder.size(),
      R"(file = "https://learnopengl.com/Advanced-OpenGL/Cubemaps", where = "Refraction")");
  std::ofstream(listing / "manifest.toml", std::ios::trunc) << manifest;

  const std::string folders =
      fmt::format(" --shaders {} --golden {} --out {} --backend gl,vk", (root / "shaders").string(),
                  (root / "golden").string(), (root / "out").string());
  EXPECT_EQ(runSnell("bless" + folders).code, 0);
  const auto run = runSnell("run" + folders);
  EXPECT_EQ(run.code, 0) << run.out;
  EXPECT_NE(run.out.find("4 results: 4 Pass"), std::string::npos) << run.out;
  fs::remove_all(root);
}

}  // namespace
}  // namespace snell
