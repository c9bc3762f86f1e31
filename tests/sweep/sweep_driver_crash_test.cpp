// A driver child that crashes or hangs part-way: the points it answered
// keep their answers, the rest become crash breaks, and the sweep returns.
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

TEST(SweepDriver, ACrashAfterTheFirstAnswerMakesTheRestCrash) {
  const fs::path script = fakeEval("crash", fmt::format("echo '{}'\nkill -SEGV $$\n", kAnswer));
  const std::vector<SweepPoint> points = threePoints();
  const BackendSweep sweep = sweepDriver(script.string(), "gl", "/dev/null", points.size(), 30);
  fs::remove(script);
  ASSERT_EQ(sweep.points.size(), 3u);
  EXPECT_TRUE(sweep.points[0].answered);
  for (std::size_t k = 1; k < 3; ++k) {
    EXPECT_FALSE(sweep.points[k].answered);
    EXPECT_NE(sweep.points[k].problem.find("signal 11"), std::string::npos)
        << sweep.points[k].problem;
    const std::vector<Break> breaks = classifyPoint(points[k], k, sweep.points[k], "gl");
    ASSERT_EQ(breaks.size(), 1u);
    EXPECT_EQ(breaks[0].kind, "crash");
    EXPECT_EQ(breaks[0].cls, BreakClass::Implementation);
  }
}

TEST(SweepDriver, AHungDriverIsCutOffAtItsTimeout) {
  const fs::path script = fakeEval("hang", "exec sleep 30\n");
  const BackendSweep sweep = sweepDriver(script.string(), "gl", "/dev/null", 2, 0.5);
  fs::remove(script);
  for (const Observation& o : sweep.points) {
    EXPECT_FALSE(o.answered);
    EXPECT_NE(o.problem.find("no answer within"), std::string::npos) << o.problem;
  }
}

}  // namespace
}  // namespace snell::sweep
