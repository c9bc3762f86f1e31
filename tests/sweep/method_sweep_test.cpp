// The method classifier: Schlick with cos(theta_i) on the dense side near
// the critical angle is a method break, the exact equations never are, and
// a weight outside [0, 1] or falling toward grazing is flagged.
#include "sweep/method_sweep.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace snell::sweep {
namespace {

std::vector<MethodSample> series(const std::string& method, double eta) {
  std::vector<MethodSample> out;
  for (double angle : anglesFor(fullGrid(), eta)) out.push_back(methodSample(method, eta, angle));
  return out;
}

bool flagged(const std::vector<Break>& breaks, const std::string& kind, double fromDeg,
             double toDeg, const std::vector<MethodSample>& samples) {
  return std::any_of(breaks.begin(), breaks.end(), [&](const Break& b) {
    const double a = samples[b.point].angleDegrees;
    return b.kind == kind && b.cls == BreakClass::Method && a >= fromDeg && a <= toDeg;
  });
}

TEST(MethodSweep, SchlickWithIncidentCosineBreaksNearTheCriticalAngleOnTheDenseSide) {
  const std::vector<MethodSample> schlick = series("schlick", 1.5);
  const std::vector<Break> breaks = methodBreaks(schlick, 0);
  // Just below 41.81 degrees exact Fresnel climbs to 1 while Schlick's
  // (1 - cos(theta_i))^5 term is still near 0.
  EXPECT_TRUE(flagged(breaks, "error_past_bound", 41.0, 41.8103, schlick));
  const MethodSample near = methodSample("schlick", 1.5, 41.81);
  EXPECT_GT(near.exact - near.value, 0.5);
}

TEST(MethodSweep, ExactFresnelNeverBreaks) {
  for (double eta : fullGrid().etas) {
    SCOPED_TRACE(eta);
    EXPECT_TRUE(methodBreaks(series("exact", eta), 0).empty());
  }
}

TEST(MethodSweep, ConstantWeightBreaksTowardGrazing) {
  const std::vector<MethodSample> constant = series("constant", 1 / 1.5);
  EXPECT_TRUE(flagged(methodBreaks(constant, 0), "error_past_bound", 80, 90, constant));
}

TEST(MethodSweep, PhysicalRangeViolationsAreFlagged) {
  std::vector<MethodSample> bad = series("exact", 1 / 1.5);
  bad[10].value = 1.2;                    // weight above 1
  bad[20].value = bad[19].value - 0.001;  // falls toward grazing
  bad[20].exact = bad[20].value;          // small error: only the fall is wrong
  const std::vector<Break> breaks = methodBreaks(bad, 0);
  EXPECT_TRUE(
      flagged(breaks, "weight_outside_0_1", bad[10].angleDegrees, bad[10].angleDegrees, bad));
  EXPECT_TRUE(
      flagged(breaks, "falls_toward_grazing", bad[20].angleDegrees, bad[20].angleDegrees, bad));
}

TEST(MethodSweep, ClassifyMethodsIndexesTheWholeSweep) {
  SweepGrid grid = quickGrid();
  grid.etas = {1.5};
  const std::vector<MethodSample> samples = methodSweep(grid);
  for (const Break& b : classifyMethods(samples)) {
    ASSERT_LT(b.point, samples.size());
    EXPECT_EQ(b.function, samples[b.point].method);
    EXPECT_NE(b.function, "exact");
  }
}

}  // namespace
}  // namespace snell::sweep
