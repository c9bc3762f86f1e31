// The full grid holds what issue 15 asks of a sweep: eta 0.3 to 2.5 with
// exactly 1 and every eta in the sources, angles to grazing, and points
// within 1e-6 rad either side of each critical angle.
#include "sweep/sweep_points.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace snell::sweep {
namespace {

bool contains(const std::vector<double>& values, double x) {
  return std::find(values.begin(), values.end(), x) != values.end();
}

TEST(SweepPoints, FullGridHoldsEveryEtaAndAngleAsked) {
  const SweepGrid grid = fullGrid();
  for (double eta : {0.3, 1.0, 2.5, 0.6, 0.65, 0.66, 0.67, 0.69, 1 / 1.1, 1 / 1.097, 1 / 1.103,
                     1.02, 0.98, 1.03, 1.06, 1.09, 0.9, 1.5})
    EXPECT_TRUE(contains(grid.etas, eta)) << eta;
  for (double angle : {0.0, 45.0, 89.0, 89.5, 89.9999, 90.0})
    EXPECT_TRUE(contains(grid.angles, angle)) << angle;
}

TEST(SweepPoints, EachCriticalAngleIsBracketedWithin1e6Radians) {
  const SweepGrid grid = fullGrid();
  for (double eta : grid.etas) {
    if (eta <= 1) continue;
    SCOPED_TRACE(eta);
    const double critical = std::asin(1 / eta) * 180 / std::numbers::pi;
    const std::vector<double> angles = anglesFor(grid, eta);
    const auto above = std::upper_bound(angles.begin(), angles.end(), critical + 1e-9);
    ASSERT_NE(above, angles.end());
    ASSERT_NE(above, angles.begin());
    EXPECT_LE((*above - *(above - 2)) * std::numbers::pi / 180, 1e-6 * 1.0001);
  }
}

TEST(SweepPoints, BadInputsCoverWhatTheListingsAssumeAway) {
  std::vector<std::string> inputs;
  for (const SweepPoint& p : sweepPoints(quickGrid())) inputs.push_back(p.input);
  for (const char* input :
       {"unnormalized-I-x2", "unnormalized-N-x3", "I=-N", "back-facing-N", "zero-I", "zero-N",
        "denormal-I", "huge-I", "nan-I", "inf-N", "nan-eta", "inf-eta"})
    EXPECT_TRUE(std::find(inputs.begin(), inputs.end(), input) != inputs.end()) << input;
}

}  // namespace
}  // namespace snell::sweep
