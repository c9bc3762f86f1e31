// A command's own outputs of an earlier run that it does not write again
// are removed when it settles its ledger; files it never wrote are kept,
// and so is everything when no ledger was there.
#include "core/output_ledger.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <string>

namespace snell {
namespace {

namespace fs = std::filesystem;

void write(const fs::path& path) {
  fs::create_directories(path.parent_path());
  std::ofstream(path) << "x";
}

TEST(OutputLedger, RemovesLastRunsOutputsNotWrittenAgainAndNothingElse) {
  const fs::path dir = fs::temp_directory_path() / ("snell-ledger-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  write(dir / "mine.txt");  // the user's, before any run
  {
    const OutputLedger first(dir);
    write(dir / "chart-gl.png");
    write(dir / "chart-vk.png");
    write(dir / "data" / "gl.dat");
    EXPECT_TRUE(first.settle().empty()) << "no ledger yet: nothing to remove";
  }
  write(dir / "later.txt");  // the user's, between runs
  // The first run ended a while ago (a file written in the last two
  // seconds is never taken as a stale one).
  for (const char* name : {"chart-gl.png", "chart-vk.png", "data/gl.dat", "later.txt"})
    fs::last_write_time(dir / name, fs::last_write_time(dir / name) - std::chrono::seconds(60));
  {
    const OutputLedger second(dir);
    write(dir / "chart-vk.png");
    const std::vector<fs::path> removed = second.settle();
    EXPECT_EQ(removed.size(), 2u);
  }
  EXPECT_FALSE(fs::exists(dir / "chart-gl.png"));
  EXPECT_FALSE(fs::exists(dir / "data" / "gl.dat"));
  EXPECT_TRUE(fs::exists(dir / "chart-vk.png"));
  EXPECT_TRUE(fs::exists(dir / "mine.txt"));
  EXPECT_TRUE(fs::exists(dir / "later.txt"));
  // A ledger naming files outside the folder removes none of them.
  std::ofstream(dir / OutputLedger::kFileName) << "../outside.txt\n/etc/hostname\n";
  write(dir.parent_path() / ("outside.txt"));
  EXPECT_TRUE(OutputLedger(dir).settle().empty());
  EXPECT_TRUE(fs::exists(dir.parent_path() / "outside.txt"));
  fs::remove(dir.parent_path() / "outside.txt");
  fs::remove_all(dir);
}

}  // namespace
}  // namespace snell
