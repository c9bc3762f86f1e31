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
