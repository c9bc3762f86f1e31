// A written file's mark (core/written_mark.h) holds while the file is the
// one written from that data, and not once the file changes in any way.
#include "core/written_mark.h"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

namespace snell {
namespace {

namespace fs = std::filesystem;

class WrittenMark : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / fmt::format("snell-written-mark-{}", getpid());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    file_ = dir_ / "image.png";
    std::ofstream(file_) << "pixels";
    markWrittenFrom(file_, digestOf("pixels"));
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_, file_;
};

TEST_F(WrittenMark, HoldsForTheSameDataAndSurvivesARename) {
  EXPECT_TRUE(writtenFrom(file_, digestOf("pixels")));
  fs::rename(file_, dir_ / "renamed.png");
  EXPECT_TRUE(writtenFrom(dir_ / "renamed.png", digestOf("pixels")));
}

TEST_F(WrittenMark, OtherDataIsNotWrittenYet) {
  EXPECT_FALSE(writtenFrom(file_, digestOf("other pixels")));
}

TEST_F(WrittenMark, AFileChangedSinceHasNoValidMark) {
  std::ofstream(file_, std::ios::app) << "!";
  EXPECT_FALSE(writtenFrom(file_, digestOf("pixels"))) << "grown";
}

TEST_F(WrittenMark, AFileTouchedSinceHasNoValidMark) {
  fs::last_write_time(file_, fs::last_write_time(file_) + std::chrono::seconds(1));
  EXPECT_FALSE(writtenFrom(file_, digestOf("pixels"))) << "same size, another time";
}

TEST_F(WrittenMark, AFileWrittenOverHasNoValidMark) {
  std::ofstream(dir_ / "new") << "pixels";
  fs::rename(dir_ / "new", file_);  // what an editor's save does
  EXPECT_FALSE(writtenFrom(file_, digestOf("pixels")));
  EXPECT_FALSE(writtenFrom(dir_ / "missing.png", digestOf("pixels")));
}

}  // namespace
}  // namespace snell
