#include "compare/vector_check.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "compare/slack.h"

namespace snell {
namespace {

OracleVarying expected3() {
  OracleVarying v;
  v.name = "R";
  v.components = 3;
  v.reference = {0.5, -0.25, 1.0};
  v.lo = {0.4999, -0.2501, 0.9999};
  v.hi = {0.5002, -0.2499, 1.0};
  v.strict = {0.5f, -0.25f, 1.0f};
  v.undefined = {0, 0, 0};
  return v;
}

TEST(Slack, ZeroAtExactValueAndOneAtTheEdge) {
  EXPECT_EQ(slack(0.5, 0.5, 0.4, 0.7), 0.0);
  EXPECT_DOUBLE_EQ(slack(0.7, 0.5, 0.4, 0.7), 1.0);
  EXPECT_DOUBLE_EQ(slack(0.4, 0.5, 0.4, 0.7), 1.0);
  EXPECT_DOUBLE_EQ(slack(0.6, 0.5, 0.4, 0.7), 0.5);  // measured on its own side
  EXPECT_GT(slack(0.71, 0.5, 0.4, 0.7), 1.0);
}

TEST(Slack, NoRoomOrNanIsInfinite) {
  EXPECT_TRUE(std::isinf(slack(1.0000001, 1.0, 0.9, 1.0)));
  EXPECT_TRUE(std::isinf(slack(std::nan(""), 1.0, 0.9, 1.1)));
  EXPECT_FALSE(withinSpec(std::nan(""), 0.9, 1.1));
}

// An infinity where the spec leaves that side unbounded (a possible
// overflow) is within it, on its edge: not NaN, which counts as outside.
TEST(Slack, AnInfinityOnAnUnboundedSideIsOnItsEdge) {
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_TRUE(withinSpec(inf, 1.0, inf));
  EXPECT_EQ(slack(inf, 2.0, 1.0, inf), 1.0);
  EXPECT_EQ(slack(-inf, 2.0, -inf, 3.0), 1.0);
  EXPECT_EQ(slack(5.0, 2.0, 1.0, inf), 0.0);
  EXPECT_TRUE(std::isinf(slack(inf, 2.0, 1.0, 3.0)));
}

TEST(VectorCheck, PassesInsideTheInterval) {
  CapturedVarying got{"R", 3, {0.5f, -0.25f, 1.0f}};
  const VaryingCheck check = checkVarying(expected3(), got);
  EXPECT_EQ(check.checked, 3u);
  EXPECT_EQ(check.failed, 0u);
  EXPECT_EQ(check.worstSlack, 0.0);
}

TEST(VectorCheck, FailsJustOutsideTheInterval) {
  const OracleVarying e = expected3();
  // One fp32 step beyond hi on the last component.
  CapturedVarying got{"R", 3, {0.5f, -0.25f, std::nextafter(1.0f, 2.0f)}};
  const VaryingCheck check = checkVarying(e, got);
  EXPECT_EQ(check.failed, 1u);
  ASSERT_EQ(check.worstFailures.size(), 1u);
  EXPECT_EQ(check.worstFailures[0].component, 2);
  EXPECT_GT(check.worstSlack, 1.0);
}

// Twenty failing samples: the eight kept are the worst by slack, worst first,
// and a failure repeated sample after sample is kept once.
// A float output exactly 0 with [-1, 1] allowed at every sample, read back
// as `observed`.
VaryingCheck checkAgainstZeroWithinOne(const std::vector<float>& observed) {
  OracleVarying e;
  e.name = "F";
  e.components = 1;
  e.reference.assign(observed.size(), 0.0);
  e.lo.assign(observed.size(), -1.0);
  e.hi.assign(observed.size(), 1.0);
  e.strict.assign(observed.size(), 0.0f);
  e.undefined.assign(observed.size(), 0);
  return checkVarying(e, CapturedVarying{"F", 1, observed});
}

TEST(VectorCheck, KeepsTheWorstFailuresOnceEach) {
  // Samples 0-9 all read 1.5 (the same failure); 10-19 read 2, 3, ... 11.
  std::vector<float> observed;
  for (int sample = 0; sample < 20; ++sample)
    observed.push_back(sample < 10 ? 1.5f : static_cast<float>(sample - 8));
  const VaryingCheck check = checkAgainstZeroWithinOne(observed);
  EXPECT_EQ(check.failed, 20u);
  ASSERT_EQ(check.worstFailures.size(), VaryingCheck::kFailuresKept);
  for (std::size_t k = 0; k < check.worstFailures.size(); ++k)
    EXPECT_EQ(check.worstFailures[k].observed, static_cast<float>(11 - k)) << k;
  EXPECT_EQ(check.worstFailures[0].vertex, 19u);
}

TEST(VectorCheck, ARepeatedFailureIsKeptOnce) {
  const VaryingCheck check = checkAgainstZeroWithinOne({1.5f, 1.5f, 1.5f, 4.0f, 1.5f});
  ASSERT_EQ(check.worstFailures.size(), 2u);
  EXPECT_EQ(check.worstFailures[0].vertex, 3u);
  EXPECT_EQ(check.worstFailures[1].vertex, 0u);  // the first of the four alike
}

TEST(VectorCheck, FailsOnNan) {
  CapturedVarying got{"R", 3, {0.5f, std::numeric_limits<float>::quiet_NaN(), 1.0f}};
  EXPECT_EQ(checkVarying(expected3(), got).failed, 1u);
}

TEST(VectorCheck, UndefinedComponentsAreCountedNotGated) {
  OracleVarying e = expected3();
  e.undefined = {0, 1, 0};
  CapturedVarying got{"R", 3, {0.5f, 1e9f, 1.0f}};
  const VaryingCheck check = checkVarying(e, got);
  EXPECT_EQ(check.failed, 0u);
  EXPECT_EQ(check.undefined, 1u);
  EXPECT_EQ(check.checked, 2u);
}

TEST(VectorCheck, SlackHistogramCountsEveryCheckedComponent) {
  EXPECT_EQ(slackBin(0.0), 0u);
  EXPECT_EQ(slackBin(1.0 / 64), 1u);  // bins are closed above
  EXPECT_EQ(slackBin(0.02), 2u);
  EXPECT_EQ(slackBin(1.0), 5u);
  EXPECT_EQ(slackBin(1.5), 6u);
  EXPECT_EQ(slackBin(std::numeric_limits<double>::infinity()), 7u);
  EXPECT_EQ(slackBin(std::nan("")), 7u);  // NaN is outside the spec
  CapturedVarying got{"R", 3, {0.5f, std::numeric_limits<float>::quiet_NaN(), 1.0f}};
  const VaryingCheck check = checkVarying(expected3(), got);
  std::size_t total = 0;
  for (std::size_t n : check.slackHistogram) total += n;
  EXPECT_EQ(total, check.checked);
  EXPECT_EQ(check.slackHistogram.back(), 1u);  // the NaN
}

TEST(VectorCheck, MismatchedShapesAreAHarnessError) {
  CapturedVarying got{"R", 3, {0.5f, -0.25f}};
  EXPECT_THROW(checkVarying(expected3(), got), std::invalid_argument);
}

}  // namespace
}  // namespace snell
