// A driver child that crashes or hangs: a crash is narrowed down to the
// point that causes it (the others answered), a hang is cut off, and the
// sweep returns either way.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "sweep/sweep_backend_run.h"
#include "sweep/sweep_classify.h"

namespace snell::sweep {
namespace {

namespace fs = std::filesystem;

// A stand-in for `snell eval`: a shell script given the same arguments.
fs::path fakeEval(const std::string& name, const std::string& body) {
  const fs::path script =
      fs::temp_directory_path() / fmt::format("snell-{}-{}.sh", name, ::getpid());
  std::ofstream(script) << "#!/bin/sh\n" << body;
  ::chmod(script.c_str(), 0755);
  return script;
}

constexpr const char* kAnswer =
    R"({"line":1,"fn":"reflect","value":[0,1,0],"exact":[0,1,0],"lo":[0,1,0],"hi":[0,1,0],)"
    R"("within_spec":true,"slack":0})";

std::vector<SweepPoint> threePoints() {
  SweepGrid grid;
  grid.angles = {0, 10, 20};
  std::vector<SweepPoint> points;
  for (const SweepPoint& p : sweepPoints(grid))
    if (p.input == "grid" && p.call.fn == "reflect") points.push_back(p);
  return points;
}

// Answers every line of its input, unless a line holds a NaN: then it dies
// of SIGSEGV before answering anything, as a driver crashing in the draw.
constexpr const char* kCrashesOnNaN =
    "if grep -q nan \"$4\"; then kill -SEGV $$; fi\n"
    "while read -r line; do echo '{}'; done < \"$4\"\n";

TEST(SweepDriver, ACrashIsPinnedToThePointThatCausesItAndTheRestAreAnswered) {
  const fs::path script = fakeEval("crash", fmt::format(kCrashesOnNaN, kAnswer));
  std::vector<SweepPoint> points = threePoints();
  for (const SweepPoint& p : sweepPoints(quickGrid()))
    if (p.input == "nan-I" && p.call.fn == "reflect") points.insert(points.begin() + 1, p);
  ASSERT_EQ(points.size(), 4u);
  const BackendSweep sweep =
      sweepDriver(script.string(), "gl", points, fs::temp_directory_path(), 30);
  fs::remove(script);
  ASSERT_EQ(sweep.points.size(), 4u);
  for (std::size_t k : {0, 2, 3}) EXPECT_TRUE(sweep.points[k].answered) << k;
  EXPECT_FALSE(sweep.points[1].answered);
  EXPECT_NE(sweep.points[1].problem.find("signal 11"), std::string::npos)
      << sweep.points[1].problem;
  EXPECT_NE(sweep.points[1].problem.find("this point alone"), std::string::npos);
  const std::vector<Break> breaks = classifyPoint(points[1], 1, sweep.points[1], "gl");
  ASSERT_EQ(breaks.size(), 1u);
  EXPECT_EQ(breaks[0].kind, "crash");
  EXPECT_EQ(breaks[0].cls, BreakClass::Implementation);
}

TEST(SweepDriver, NarrowingStopsAtItsBudget) {
  const fs::path script = fakeEval("always", "kill -SEGV $$\n");
  const BackendSweep sweep =
      sweepDriver(script.string(), "gl", threePoints(), fs::temp_directory_path(), 30, 1);
  fs::remove(script);
  for (const Observation& o : sweep.points) {
    EXPECT_FALSE(o.answered);
    EXPECT_NE(o.problem.find("in a batch of 3 points"), std::string::npos) << o.problem;
  }
}

TEST(SweepDriver, AHungDriverIsCutOffAtItsTimeout) {
  const fs::path script = fakeEval("hang", "exec sleep 30\n");
  std::vector<SweepPoint> points = threePoints();
  const BackendSweep sweep =
      sweepDriver(script.string(), "gl", points, fs::temp_directory_path(), 0.5);
  fs::remove(script);
  for (const Observation& o : sweep.points) {
    EXPECT_FALSE(o.answered);
    EXPECT_NE(o.problem.find("no answer within 0.5 s (--timeout)"), std::string::npos) << o.problem;
  }
  // Cut off at the limit is a timeout, not a crash: the limit may be the
  // user's, set too short.
  const std::vector<Break> breaks = classifyPoint(points[0], 0, sweep.points[0], "gl");
  ASSERT_EQ(breaks.size(), 1u);
  EXPECT_EQ(breaks[0].kind, "timeout");
}

}  // namespace
}  // namespace snell::sweep
