// WatchedFiles notices each way a file can change under a running process.
#include "core/watched_files.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/mman.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "core/errors.h"

namespace {

namespace fs = std::filesystem;
using snell::WatchedFiles;

struct WatchedFile : ::testing::Test {
  fs::path dir = fs::temp_directory_path() / fmt::format("snell-watched-{}", ::getpid());
  fs::path file = dir / "driver.so";
  void SetUp() override {
    fs::create_directories(dir);
    std::ofstream(file) << "version 1";
  }
  void TearDown() override { fs::remove_all(dir); }
};

TEST_F(WatchedFile, UnchangedFilesAreNotReported) {
  const WatchedFiles watched = WatchedFiles::ofThisProcess({file.string()});
  EXPECT_GT(watched.size(), 1u) << "the process's own mapped files are watched too";
  EXPECT_EQ(watched.firstChanged(), std::nullopt);
}

TEST_F(WatchedFile, RewrittenInPlaceIsReported) {
  const WatchedFiles watched = WatchedFiles::ofThisProcess({file.string()});
  std::ofstream(file) << "version 2";  // same inode, new size and time
  EXPECT_EQ(watched.firstChanged(), file.string());
}

TEST_F(WatchedFile, TouchedIsReported) {
  const WatchedFiles watched = WatchedFiles::ofThisProcess({file.string()});
  fs::last_write_time(file, fs::last_write_time(file) + std::chrono::seconds(5));
  EXPECT_EQ(watched.firstChanged(), file.string());
}

TEST_F(WatchedFile, ReplacedByRenameIsReported) {
  const WatchedFiles watched = WatchedFiles::ofThisProcess({file.string()});
  const fs::path next = dir / "driver.so.new";
  std::ofstream(next) << "version 1";  // same size: only the inode tells
  fs::rename(next, file);
  EXPECT_EQ(watched.firstChanged(), file.string());
}

TEST_F(WatchedFile, RemovedIsReported) {
  const WatchedFiles watched = WatchedFiles::ofThisProcess({file.string()});
  fs::remove(file);
  EXPECT_EQ(watched.firstChanged(), file.string());
}

TEST_F(WatchedFile, ADataFileMappedByTheProcessIsNotCode) {
  // As a driver maps its shader cache's index, which changes as it fills.
  const int fd = ::open(file.c_str(), O_RDONLY);
  ASSERT_GE(fd, 0);
  void* data = ::mmap(nullptr, 9, PROT_READ, MAP_SHARED, fd, 0);
  ASSERT_NE(data, MAP_FAILED);
  const WatchedFiles watched = WatchedFiles::ofThisProcess();
  std::ofstream(file) << "version 2";
  EXPECT_EQ(watched.firstChanged(), std::nullopt);
  ::munmap(data, 9);
  ::close(fd);
}

TEST_F(WatchedFile, AFileThatCannotBeReadIsAUsageError) {
  EXPECT_THROW(WatchedFiles::ofThisProcess({(dir / "missing").string()}), snell::UsageError);
}

}  // namespace
