// Result files land whole under their final name or not at all.
#include "core/atomic_file.h"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include "core/errors.h"

namespace snell {
namespace {

namespace fs = std::filesystem;

fs::path scratch() {
  const fs::path dir = fs::temp_directory_path() / fmt::format("snell-atomic-{}", getpid());
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

TEST(AtomicFile, ReplacesTheWholeFile) {
  const fs::path dir = scratch();
  std::ofstream(dir / "r.jsonl") << "old, longer than the new text\n";
  writeFileAtomically(dir / "r.jsonl", "new\n");
  EXPECT_EQ(text(dir / "r.jsonl"), "new\n");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
  fs::remove_all(dir);
}

// A worker killed while it wrote leaves its temporaries (FILE.tmpPID, and
// FILE.tmpPID.EXT as the image module names them): those of that process
// are removed, another process's and the files themselves are kept.
TEST(AtomicFile, TheTemporariesOfAKilledProcessAreRemoved) {
  const fs::path dir = scratch();
  for (const char* name : {"gl.exr", "gl.exr.tmp740.exr", "mask.png.tmp740.png", "r.jsonl.tmp740",
                           "gl.exr.tmp7401.exr", "vk.exr.tmp741.exr", ".tmp740"})
    std::ofstream(dir / name) << "x";
  removeTemporaryFilesOf(740, dir);
  std::set<std::string> left;
  for (const auto& entry : fs::directory_iterator(dir)) left.insert(entry.path().filename());
  EXPECT_EQ(left, (std::set<std::string>{"gl.exr", "gl.exr.tmp7401.exr", "vk.exr.tmp741.exr",
                                         ".tmp740"}));
  removeTemporaryFilesOf(740, dir / "no-such-folder");  // nothing to do, no error
  fs::remove_all(dir);
}

// A folder where the file should go is the user's mistake: one clear
// message (no "internal error: filesystem error"), the folder untouched and
// no temporary file left beside it.
TEST(AtomicFile, AFolderInTheWayIsAUsageErrorThatLeavesNothing) {
  const fs::path dir = scratch();
  fs::create_directories(dir / "results.jsonl");
  try {
    writeFileAtomically(dir / "results.jsonl", "x\n");
    FAIL() << "no error";
  } catch (const UsageError& error) {
    EXPECT_NE(std::string(error.what()).find("results.jsonl: cannot be written"), std::string::npos)
        << error.what();
  }
  EXPECT_TRUE(fs::is_directory(dir / "results.jsonl"));
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
  fs::remove_all(dir);
}

// A run that stops on an error before its first record leaves no empty
// FILE.partial (which the next run would take for a killed run's results);
// one with records keeps them for --resume.
TEST(StreamingFile, AnUnfinishedFileKeepsItsPartialOnlyWhenItHoldsRecords) {
  const fs::path dir = scratch();
  { StreamingFile empty(dir / "empty.jsonl"); }
  EXPECT_FALSE(fs::exists(dir / "empty.jsonl.partial"));
  {
    StreamingFile some(dir / "some.jsonl");
    some.writeLine("{\"case\":\"a\"}");
  }
  EXPECT_EQ(text(dir / "some.jsonl.partial"), "{\"case\":\"a\"}\n");
  {
    StreamingFile done(dir / "done.jsonl");
    done.finish("all\n");
  }
  EXPECT_EQ(text(dir / "done.jsonl"), "all\n");
  EXPECT_FALSE(fs::exists(dir / "done.jsonl.partial"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace snell
