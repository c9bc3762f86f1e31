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
  std::ofstream(file) << "version 22";  // same inode, a new size (and time)
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

// `file` mapped into this process as `protection`, for the life of the
// object (a driver library, or the shader cache index a driver maps).
struct Mapping {
  void* data = MAP_FAILED;
  int fd = -1;
  Mapping(const fs::path& path, int protection) : fd(::open(path.c_str(), O_RDONLY)) {
    if (fd >= 0) data = ::mmap(nullptr, 9, protection, MAP_PRIVATE, fd, 0);
  }
  ~Mapping() {
    if (data != MAP_FAILED) ::munmap(data, 9);
    if (fd >= 0) ::close(fd);
  }
};

TEST_F(WatchedFile, ADataFileMappedByTheProcessIsNotCode) {
  const Mapping mapped(file, PROT_READ);
  ASSERT_NE(mapped.data, MAP_FAILED);
  const WatchedFiles watched = WatchedFiles::ofThisProcess();
  std::ofstream(file) << "version 22";
  fs::last_write_time(file, fs::last_write_time(file) + std::chrono::seconds(5));
  EXPECT_EQ(watched.firstChanged(), std::nullopt);
}

TEST_F(WatchedFile, CodeMappedByTheProcessIsWatched) {
  const Mapping mapped(file, PROT_READ | PROT_EXEC);
  if (mapped.data == MAP_FAILED) GTEST_SKIP() << "the temporary folder is mounted noexec";
  const WatchedFiles watched = WatchedFiles::ofThisProcess();
  EXPECT_EQ(watched.firstChanged(), std::nullopt);
  fs::last_write_time(file, fs::last_write_time(file) + std::chrono::seconds(5));
  EXPECT_EQ(watched.firstChanged(), file.string());
}

TEST_F(WatchedFile, CodeRemovedBeforeTheSnapshotIsAlreadyChanged) {
  // A library reinstalled while the process was still starting: its code
  // is loaded, and the file at its path is another.
  const Mapping mapped(file, PROT_READ | PROT_EXEC);
  if (mapped.data == MAP_FAILED) GTEST_SKIP() << "the temporary folder is mounted noexec";
  const fs::path next = dir / "driver.so.new";
  std::ofstream(next) << "version 1";
  fs::rename(next, file);
  const WatchedFiles watched = WatchedFiles::ofThisProcess();
  EXPECT_EQ(watched.firstChanged(), file.string());
}

TEST_F(WatchedFile, ExecutableMemoryWithNoFileIsNotWatched) {
  // As a JIT may map its code ("/memfd:NAME (deleted)" in the maps): no
  // file on disk, so nothing that can be rebuilt.
  const int fd = ::memfd_create("snell-watched-test", MFD_CLOEXEC);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(::ftruncate(fd, 4096), 0);
  void* code = ::mmap(nullptr, 4096, PROT_READ | PROT_EXEC, MAP_PRIVATE, fd, 0);
  if (code == MAP_FAILED) {
    ::close(fd);
    GTEST_SKIP() << "executable memfd mappings are not allowed here";
  }
  const WatchedFiles watched = WatchedFiles::ofThisProcess();
  EXPECT_EQ(watched.firstChanged(), std::nullopt);
  ::munmap(code, 4096);
  ::close(fd);
}

TEST_F(WatchedFile, AFileThatCannotBeReadIsAUsageError) {
  EXPECT_THROW(WatchedFiles::ofThisProcess({(dir / "missing").string()}), snell::UsageError);
}

}  // namespace
