// The oracle's refract() switches to the zero vector where the closed form
// asin(n2 / n1) says, to the sweep's resolution.
#include "sweep/critical_angle.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "sweep/sweep_backend_run.h"

namespace snell::sweep {
namespace {

TEST(CriticalAngle, OracleSwitchesAtTheClosedFormForSeveralEtas) {
  SweepGrid grid = fullGrid();
  grid.etas = {1.02, 1.1, 1.333, 1.5, 2.5};
  std::vector<SweepPoint> points;
  for (const SweepPoint& p : sweepPoints(grid))
    if (p.input == "grid" && p.call.fn == "refract") points.push_back(p);
  const BackendSweep oracle = sweepOracle(points);
  const std::vector<CriticalAngle> found = criticalAngles(points, oracle, oracle);
  ASSERT_EQ(found.size(), grid.etas.size());
  for (const CriticalAngle& c : found) {
    SCOPED_TRACE(c.eta);
    const double closed = std::asin(1.0 / c.eta) * 180.0 / std::numbers::pi;
    EXPECT_DOUBLE_EQ(c.closedFormDegrees, closed);
    EXPECT_TRUE(c.agrees);
    EXPECT_EQ(c.wrongSide, 0);
    // The grid brackets each critical angle with points 5e-7 rad either side.
    EXPECT_LE(c.resolutionDegrees, 1e-6 * 180.0 / std::numbers::pi * 1.0001);
    const double tangent = std::tan(closed * std::numbers::pi / 180.0);
    EXPECT_DOUBLE_EQ(c.inputRoundingDegrees,
                     std::ldexp(tangent + 1 / tangent, -24) * 180.0 / std::numbers::pi);
    EXPECT_NEAR(c.foundDegrees, closed,
                0.5 * c.resolutionDegrees + c.specBandDegrees + c.inputRoundingDegrees);
  }
  EXPECT_NEAR(found[3].foundDegrees, 41.81, 0.005);  // n = 1.5
}

TEST(CriticalAngle, ASwitchOnTheWrongSideDisagrees) {
  SweepGrid grid = quickGrid();
  grid.etas = {1.5};
  std::vector<SweepPoint> points;
  for (const SweepPoint& p : sweepPoints(grid))
    if (p.input == "grid" && p.call.fn == "refract") points.push_back(p);
  const BackendSweep oracle = sweepOracle(points);
  BackendSweep early = oracle;
  early.backend = "early";
  // A backend that gives up 1e-3 rad before the critical angle.
  for (std::size_t k = 0; k < points.size(); ++k)
    if (points[k].angleDegrees > 41.81 - 0.06 && points[k].angleDegrees < 41.81)
      early.points[k].value = {0, 0, 0};
  const std::vector<CriticalAngle> found = criticalAngles(points, oracle, early);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_FALSE(found[0].agrees);
  EXPECT_GT(found[0].wrongSide, 0);
}

}  // namespace
}  // namespace snell::sweep
