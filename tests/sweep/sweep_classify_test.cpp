// The builtin classifier on known points: refract()'s zero vector under
// total internal reflection and a NaN input are undefined, a wrong value
// injected into a backend is an implementation break, and no NaN or
// infinite input stops the sweep.
#include "sweep/sweep_classify.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "oracle/builtin_probe.h"
#include "sweep/sweep_backend_run.h"

namespace snell::sweep {
namespace {

SweepPoint refractAt(double degrees, double eta) {
  SweepGrid grid;
  grid.etas = {eta};
  grid.angles = {degrees};
  for (const SweepPoint& p : sweepPoints(grid))
    if (p.input == "grid" && p.call.fn == "refract" && p.angleDegrees == degrees) return p;
  throw std::logic_error("no such point");
}

bool has(const std::vector<Break>& breaks, const std::string& kind, BreakClass cls) {
  return std::any_of(breaks.begin(), breaks.end(),
                     [&](const Break& b) { return b.kind == kind && b.cls == cls; });
}

// The oracle's observation with the backend's value replaced, judged again.
Observation withValue(const SweepPoint& point, std::vector<float> value) {
  Observation o = sweepOracle({point}).points.front();
  const BuiltinResult result = evaluateBuiltin(point.call);
  o.value.assign(value.begin(), value.end());
  o.withinSpec = result.allows(value);
  return o;
}

TEST(SweepClassify, TotalInternalReflectionZeroVectorIsUndefinedAsADirection) {
  const SweepPoint point = refractAt(60, 1.5);  // past 41.81 degrees
  const Observation o = sweepOracle({point}).points.front();
  ASSERT_TRUE(o.withinSpec);
  const std::vector<Break> breaks = classifyPoint(point, 0, o, "oracle");
  ASSERT_EQ(breaks.size(), 1u);
  EXPECT_EQ(breaks[0].kind, "zero_vector_direction");
  EXPECT_EQ(breaks[0].cls, BreakClass::Undefined);
}

TEST(SweepClassify, ACorrectValueIsNoBreak) {
  const SweepPoint point = refractAt(30, 0.66);
  EXPECT_TRUE(classifyPoint(point, 0, sweepOracle({point}).points.front(), "oracle").empty());
}

TEST(SweepClassify, NaNInputIsUndefined) {
  std::vector<SweepPoint> bad;
  for (const SweepPoint& p : sweepPoints(quickGrid()))
    if (p.input == "nan-I" || p.input == "nan-eta") bad.push_back(p);
  ASSERT_EQ(bad.size(), 5u);  // nan-I and nan-eta for refract at two etas, nan-I for reflect
  for (std::size_t k = 0; k < bad.size(); ++k) {
    SCOPED_TRACE(bad[k].input + " " + bad[k].call.fn);
    // A driver that returns NaN there breaks nothing the spec promised.
    const Observation o = withValue(bad[k], {NAN, NAN, NAN});
    const std::vector<Break> breaks = classifyPoint(bad[k], k, o, "gl");
    ASSERT_FALSE(breaks.empty());
    for (const Break& b : breaks) EXPECT_EQ(b.cls, BreakClass::Undefined) << b.kind;
  }
}

TEST(SweepClassify, AWrongBackendValueIsAnImplementationBreak) {
  const SweepPoint point = refractAt(30, 0.66);
  const Observation right = sweepOracle({point}).points.front();
  std::vector<float> wrong(right.value.begin(), right.value.end());
  wrong[0] += 1e-3f;  // thousands of ulps off
  const Observation o = withValue(point, wrong);
  ASSERT_FALSE(o.withinSpec);
  EXPECT_TRUE(has(classifyPoint(point, 0, o, "gl"), "outside_spec", BreakClass::Implementation));

  BackendSweep good{"vk", "", {right}}, bad{"gl", "", {o}};
  EXPECT_TRUE(
      has(disagreements({point}, good, bad), "backend_disagreement", BreakClass::Implementation));
  EXPECT_TRUE(disagreements({point}, good, good).empty());

  // A NaN where the inputs are finite and the spec gives a number.
  EXPECT_TRUE(has(classifyPoint(point, 0, withValue(point, {NAN, 0, 0}), "gl"), "nan_or_inf_output",
                  BreakClass::Implementation));
}

TEST(SweepClassify, AJumpNoSlopeAllowsIsADiscontinuity) {
  SweepGrid grid;
  grid.etas = {0.66};
  grid.angles = {10, 11, 12, 13};
  std::vector<SweepPoint> points;
  for (const SweepPoint& p : sweepPoints(grid))
    if (p.input == "grid" && p.call.fn == "refract") points.push_back(p);
  const BackendSweep smooth = sweepOracle(points);
  EXPECT_TRUE(discontinuities(points, smooth).empty());
  BackendSweep jumpy = smooth;
  jumpy.points[2] = withValue(points[2], {0.5f, -0.5f, 0.0f});
  const std::vector<Break> breaks = discontinuities(points, jumpy);
  EXPECT_TRUE(has(breaks, "discontinuity", BreakClass::Implementation));
}

TEST(SweepClassify, NoNaNOrInfiniteInputStopsTheSweep) {
  std::vector<SweepPoint> bad;
  for (const SweepPoint& p : sweepPoints(quickGrid()))
    if (p.input != "grid") bad.push_back(p);
  ASSERT_GT(bad.size(), 40u);
  const BackendSweep oracle = sweepOracle(bad);
  ASSERT_EQ(oracle.points.size(), bad.size());
  for (const Observation& o : oracle.points) EXPECT_TRUE(o.answered);
  const std::vector<Break> breaks = classifySweep(bad, {oracle});
  for (const Break& b : breaks) {
    if (!inputsFinite(bad[b.point])) {
      EXPECT_EQ(b.cls, BreakClass::Undefined) << b.kind;
    }
  }
}

TEST(SweepClassify, ReadsEvalAnswersWithNonFiniteNumbers) {
  const Observation o = observationFromAnswer(
      R"({"line":1,"fn":"refract","value":["nan",0,"inf"],"exact":["nan",0,0],"lo":["-inf",0,0],)"
      R"("hi":["inf",0,0],"within_spec":false,"slack":"inf","undefined":[true,false,false]})");
  EXPECT_TRUE(o.answered);
  EXPECT_TRUE(std::isnan(o.value[0]));
  EXPECT_TRUE(std::isinf(o.value[2]));
  EXPECT_FALSE(o.withinSpec);
  EXPECT_TRUE(o.undefined);
  EXPECT_FALSE(observationFromAnswer(R"({"line":2,"error":"line 2: bad"})").answered);
}

}  // namespace
}  // namespace snell::sweep
