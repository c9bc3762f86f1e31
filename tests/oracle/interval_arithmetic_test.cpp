// Interval + - * / against the precision rules, with the exact results taken
// from long double (64-bit significand: exact for the products and sums of
// the floats used here).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "oracle/interval.h"
#include "oracle/precision_rules.h"

namespace snell {
namespace {

constexpr float kFloatInf = std::numeric_limits<float>::infinity();

float below(float f) { return std::nextafter(f, -kFloatInf); }
float above(float f) { return std::nextafter(f, kFloatInf); }

// The floats a correctly rounded operation may return for an exact value:
// the value itself when it is a float, else the floats on either side.
void expectCorrectlyRounded(const Interval& r, long double exact) {
  const float nearest = static_cast<float>(exact);
  if (static_cast<long double>(nearest) == exact) {
    EXPECT_EQ(r.lo, nearest);
    EXPECT_EQ(r.hi, nearest);
  } else {
    const float lower = static_cast<long double>(nearest) < exact ? nearest : below(nearest);
    EXPECT_EQ(r.lo, lower);
    EXPECT_EQ(r.hi, above(lower));
  }
}

// Normal floats in [-4, 4], exponents no lower than 2^-20: sums and products
// of two are exact in long double.
float randomFloat(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> mantissa(0.5, 1.0);
  std::uniform_int_distribution<int> exponent(-20, 3);
  std::bernoulli_distribution negative;
  const float f = static_cast<float>(std::ldexp(mantissa(rng), exponent(rng)));
  return negative(rng) ? -f : f;
}

TEST(OracleIntervalArithmetic, ExactResultIsThatFloatOnly) {
  const Interval sum = Interval::point(1.0f) + Interval::point(2.0f);
  EXPECT_EQ(sum.lo, 3.0);
  EXPECT_EQ(sum.hi, 3.0);
  const Interval product = Interval::point(1.5f) * Interval::point(-0.25f);
  EXPECT_EQ(product.lo, -0.375);
  EXPECT_EQ(product.hi, -0.375);
}

TEST(OracleIntervalArithmetic, InexactResultAdmitsBothNeighbouringFloats) {
  const Interval sum = Interval::point(1.0f) + Interval::point(0x1p-30f);
  EXPECT_EQ(sum.lo, 1.0);
  EXPECT_EQ(sum.hi, 1.0 + 0x1p-23);
  const float x = 1.0f + 0x1p-23f;
  const Interval square = Interval::point(x) * Interval::point(x);  // 1 + 2^-22 + 2^-46
  EXPECT_EQ(square.lo, 1.0 + 0x1p-22);
  EXPECT_EQ(square.hi, 1.0 + 0x1p-22 + 0x1p-23);
}

TEST(OracleIntervalArithmetic, ResultsBeyondDoublePrecisionStillGetBothNeighbours) {
  // 1 +- 2^-60 rounds to 1 in double; the exact value is still not a float.
  const Interval up = Interval::point(1.0f) + Interval::point(0x1p-60f);
  EXPECT_EQ(up.lo, 1.0);
  EXPECT_EQ(up.hi, 1.0 + 0x1p-23);
  const Interval down = Interval::point(1.0f) - Interval::point(0x1p-60f);
  EXPECT_EQ(down.lo, 1.0 - 0x1p-24);
  EXPECT_EQ(down.hi, 1.0);
  const Interval product =
      Interval(1.0 + 0x1p-52, 1.0 + 0x1p-52) * Interval::point(1.0f + 0x1p-23f);
  EXPECT_EQ(product.lo, 1.0 + 0x1p-23);
  EXPECT_EQ(product.hi, 1.0 + 0x1p-22);
}

TEST(OracleIntervalArithmetic, RandomPointOperationsAreCorrectlyRounded) {
  std::mt19937_64 rng(7);
  for (int trial = 0; trial < 20000; ++trial) {
    const float a = randomFloat(rng);
    const float b = randomFloat(rng);
    const Interval A = Interval::point(a);
    const Interval B = Interval::point(b);
    const long double la = a;
    const long double lb = b;
    expectCorrectlyRounded(A + B, la + lb);
    expectCorrectlyRounded(A - B, la - lb);
    expectCorrectlyRounded(A * B, la * lb);
    EXPECT_TRUE(contains(A + B, a + b));
    EXPECT_TRUE(contains(A * B, a * b));
    if (::testing::Test::HasFailure()) FAIL() << a << " " << b;
  }
}

TEST(OracleIntervalArithmetic, OperandRangesGiveTheRangeOfResults) {
  const Interval a(-1.0, 2.0);
  const Interval b(3.0, 4.0);
  const Interval product = a * b;
  EXPECT_EQ(product.lo, -4.0);
  EXPECT_EQ(product.hi, 8.0);
  const Interval difference = a - b;
  EXPECT_EQ(difference.lo, -5.0);
  EXPECT_EQ(difference.hi, -1.0);
  const Interval negated = -a;
  EXPECT_EQ(negated.lo, -2.0);
  EXPECT_EQ(negated.hi, 1.0);
}

TEST(OracleIntervalArithmetic, DivisionAdmitsExactlyTheFloatsWithin2Point5Ulp) {
  std::mt19937_64 rng(11);
  for (int trial = 0; trial < 5000; ++trial) {
    const float a = randomFloat(rng);
    const float b = randomFloat(rng);
    const Interval q = Interval::point(a) / Interval::point(b);
    const long double exact = static_cast<long double>(a) / b;
    const long double allowed = 2.5L * ulp(static_cast<double>(exact));
    float candidate = static_cast<float>(exact);
    for (int step = 0; step < 5; ++step) candidate = below(candidate);
    for (int step = 0; step < 11; ++step, candidate = above(candidate)) {
      const bool within = std::fabs(static_cast<long double>(candidate) - exact) <= allowed;
      ASSERT_EQ(contains(q, candidate), within) << a << " / " << b << " candidate " << candidate;
    }
  }
}

// An exact quotient that is a power of two: the gap below 64 is half the gap
// above, so 2.5 ULP reach two floats on either side and no further. A double
// quotient widened by one double ULP either way used to reach the larger gap
// above 64 and admit a fifth float below it.
TEST(OracleIntervalArithmetic, ExactPowerOfTwoQuotientIsNotWidenedIntoTheGapAbove) {
  const Interval q =
      Interval::point(0.012243230827152729f) / Interval::point(0.00019130048167426139f);
  EXPECT_EQ(q.lo, 64.0 - 0x1p-17);
  EXPECT_EQ(q.hi, 64.0 + 0x1p-17);
  const Interval third = Interval::point(1.0f) / Interval::point(3.0f);
  EXPECT_TRUE(contains(third, static_cast<float>(1.0 / 3.0)));
  EXPECT_LT(third.lo, third.hi);
}

TEST(OracleIntervalArithmetic, DivisorThatMayBeZeroOrTinyIsUnconstrained) {
  const Interval byStraddle = Interval::point(1.0f) / Interval(-1.0, 1.0);
  EXPECT_TRUE(byStraddle.undefined);
  EXPECT_TRUE(contains(byStraddle, std::numeric_limits<float>::quiet_NaN()));
  EXPECT_TRUE((Interval::point(1.0f) / Interval::point(0.0f)).undefined);
  // Outside |b| in [2^-126, 2^126] the rule gives no bound.
  EXPECT_TRUE((Interval::point(1.0f) / Interval::point(0x1p127f)).undefined);
  EXPECT_FALSE((Interval::point(1.0f) / Interval::point(0x1p-126f)).undefined);
  EXPECT_FALSE((Interval::point(1.0f) / Interval::point(3.0f)).undefined);
}

TEST(OracleIntervalArithmetic, DenormalResultsMayBeFlushedToZero) {
  const Interval input = Interval::point(1e-40f);
  EXPECT_TRUE(contains(input, 0.0f));
  EXPECT_TRUE(contains(input, 1e-40f));
  const Interval tiny = Interval::point(1e-20f) * Interval::point(1e-20f);
  EXPECT_TRUE(contains(tiny, 0.0f));
  EXPECT_TRUE(contains(tiny, 1e-20f * 1e-20f));
  const Interval normal = Interval::point(1e-18f) * Interval::point(1e-18f);
  EXPECT_FALSE(contains(normal, 0.0f));
}

TEST(OracleIntervalArithmetic, OverflowAdmitsInfinity) {
  const Interval big = Interval::point(3e38f) * Interval::point(2.0f);
  EXPECT_TRUE(contains(big, kFloatInf));
  EXPECT_FALSE(contains(big, 3e38f));
}

TEST(OracleIntervalArithmetic, ContainsIsFalseForNanUnlessUndefined) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  EXPECT_FALSE(contains(Interval(-kFloatInf, kFloatInf), nan));
  EXPECT_TRUE(contains(Interval::unconstrained(), nan));
  EXPECT_TRUE(Interval::point(nan).undefined);
  EXPECT_TRUE((Interval::unconstrained() + Interval::point(1.0f)).undefined);
  EXPECT_TRUE((Interval::point(2.0f) * Interval::unconstrained()).undefined);
}

TEST(OracleIntervalArithmetic, ComparisonIsKnownOnlyWhenEveryValueAgrees) {
  EXPECT_EQ(Interval(1.0, 2.0) < Interval(3.0, 4.0), Truth::True);
  EXPECT_EQ(Interval(3.0, 4.0) < Interval(1.0, 2.0), Truth::False);
  EXPECT_EQ(Interval(1.0, 3.0) < Interval(2.0, 4.0), Truth::Unknown);
  EXPECT_EQ(Interval(0.0, 0.0) < Interval(0.0, 0.0), Truth::False);
  EXPECT_EQ(Interval::unconstrained() < Interval(0.0, 0.0), Truth::Unknown);
}

TEST(OracleIntervalArithmetic, HullAndWidth) {
  const Interval h = hull(Interval(1.0, 2.0), Interval(-3.0, -2.5));
  EXPECT_EQ(h.lo, -3.0);
  EXPECT_EQ(h.hi, 2.0);
  EXPECT_EQ(width(h), 5.0);
  EXPECT_TRUE(hull(Interval(1.0, 2.0), Interval::unconstrained()).undefined);
}

// Vulkan may distribute a division's dividend over the reciprocal:
// (a + b) / c as a * (1 / c) + b * (1 / c). With 1 / 3 rounded to
// 0x3eaaaaab, b * (1 / 3) rounds to -0x3eaaaaaa and the sum is 2^-25, far
// from the exact (a + b) / 3 = 2^-24 / 3.
TEST(OracleIntervalArithmetic, VulkanMayDistributeADividendOverTheReciprocal) {
  const Interval a = Interval::point(1.0f);
  const Interval b = Interval::point(-0.99999994f);
  const Interval c = Interval::point(3.0f);
  const float reciprocal = 1.0f / 3.0f;
  ASSERT_EQ(reciprocal, 0x1.555556p-2f);
  const float distributed = 1.0f * reciprocal + (-0.99999994f * reciprocal);
  ASSERT_EQ(distributed, 0x1p-25f);
  {
    const UsePrecisionRules use(PrecisionRules::Vulkan);
    EXPECT_TRUE(contains((a + b) / c, distributed));
  }
  const UsePrecisionRules use(PrecisionRules::Glsl);
  EXPECT_FALSE(contains((a + b) / c, distributed));
}

// A literal whose double is exactly halfway between two floats: the decimal
// 1.00000005960464477539062500001 reads as the double 1 + 2^-24, which ties
// to 1 as a float, while the decimal rounded at once is 1 + 2^-23.
TEST(OracleIntervalArithmetic, ALiteralOnAFloatMidpointMayBeEitherFloat) {
  const Interval tie = Interval::literal(1.00000005960464477539062500001);
  EXPECT_TRUE(contains(tie, 1.0f));
  EXPECT_TRUE(contains(tie, 1.00000012f));
  const Interval notTie = Interval::literal(0.1);
  EXPECT_EQ(notTie.lo, notTie.hi);
  EXPECT_EQ(notTie.lo, static_cast<double>(0.1f));
}

}  // namespace
}  // namespace snell
