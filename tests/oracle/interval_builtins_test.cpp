// The built-ins' bounds against the precision rules, with exact values from
// long double libm, and dot()'s freedom of order against every order.
#include "oracle/interval_builtins.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <random>

namespace snell {
namespace {

constexpr float kFloatInf = std::numeric_limits<float>::infinity();

float below(float f) { return std::nextafter(f, -kFloatInf); }
float above(float f) { return std::nextafter(f, kFloatInf); }

// Checks the floats around `exact` one by one: the interval must hold
// exactly those within `tolerance` of it.
void expectExactlyWithin(const Interval& r, long double exact, long double tolerance,
                         const char* what, float x) {
  float candidate = static_cast<float>(exact);
  for (int step = 0; step < 20; ++step) candidate = below(candidate);
  for (int step = 0; step < 41; ++step, candidate = above(candidate)) {
    const bool within = std::fabs(static_cast<long double>(candidate) - exact) <= tolerance;
    ASSERT_EQ(contains(r, candidate), within) << what << "(" << x << ") candidate " << candidate;
  }
}

double ulpOf(long double exact) { return ulp(static_cast<double>(exact)); }

TEST(OracleIntervalBuiltins, InversesqrtAdmitsExactlyTheFloatsWithin2Ulp) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> x(0.01, 100.0);
  for (int trial = 0; trial < 2000; ++trial) {
    const float v = static_cast<float>(x(rng));
    const long double exact = 1.0L / std::sqrt(static_cast<long double>(v));
    expectExactlyWithin(inversesqrt(Interval::point(v)), exact, 2.0L * ulpOf(exact), "inversesqrt",
                        v);
  }
  // At a power of two the ULP is the gap above it: four floats below 0.5.
  expectExactlyWithin(inversesqrt(Interval::point(4.0f)), 0.5L, 2.0L * 0x1p-24L, "inversesqrt",
                      4.0f);
  EXPECT_TRUE(contains(inversesqrt(Interval::point(4.0f)), 0.5f - 4 * 0x1p-25f));
  EXPECT_FALSE(contains(inversesqrt(Interval::point(4.0f)), 0.5f - 5 * 0x1p-25f));
}

TEST(OracleIntervalBuiltins, InversesqrtIsUndefinedAtAndBelowZero) {
  EXPECT_TRUE(inversesqrt(Interval::point(0.0f)).undefined);
  EXPECT_TRUE(inversesqrt(Interval(-1.0, 4.0)).undefined);
}

TEST(OracleIntervalBuiltins, SqrtIsInheritedFromOneOverInversesqrt) {
  const Interval two = sqrt(Interval::point(4.0f));
  EXPECT_TRUE(contains(two, 2.0f));
  // 2 ULP of inversesqrt then 2.5 ULP of the division: no more than 5 ULP
  // of 2 (2^-22) either side.
  EXPECT_LE(two.hi - 2.0, 5 * 0x1p-22);
  EXPECT_LE(2.0 - two.lo, 5 * 0x1p-22);
  EXPECT_GT(width(two), 0.0);
  const Interval root2 = sqrt(Interval::point(2.0f));
  EXPECT_TRUE(contains(root2, std::sqrt(2.0f)));
  EXPECT_TRUE(contains(root2, std::sqrt(2.0)));
}

TEST(OracleIntervalBuiltins, SqrtOfZeroIsZeroAndOfANegativeIsUndefined) {
  const Interval zero = sqrt(Interval::point(0.0f));
  EXPECT_EQ(zero.lo, 0.0);
  EXPECT_EQ(zero.hi, 0.0);
  const Interval fromZero = sqrt(Interval(0.0, 0.25));
  EXPECT_TRUE(contains(fromZero, 0.0f));
  EXPECT_TRUE(contains(fromZero, 0.5f));
  EXPECT_FALSE(contains(fromZero, 0.51f));
  EXPECT_TRUE(sqrt(Interval(-1e-7, 0.25)).undefined);
}

TEST(OracleIntervalBuiltins, Exp2AdmitsExactlyTheFloatsWithin3Plus2AbsXUlp) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> x(-6.0, 6.0);
  for (int trial = 0; trial < 2000; ++trial) {
    const float v = static_cast<float>(x(rng));
    const long double exact = std::exp2(static_cast<long double>(v));
    const long double ulps = 3.0L + 2.0L * std::fabs(static_cast<long double>(v));
    expectExactlyWithin(exp2(Interval::point(v)), exact, ulps * ulpOf(exact), "exp2", v);
  }
}

TEST(OracleIntervalBuiltins, Log2HasAnAbsoluteBoundInsideHalfToTwoAnd3UlpOutside) {
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> inside(0.5, 2.0);
  std::uniform_real_distribution<double> logOutside(-8.0, 8.0);
  for (int trial = 0; trial < 2000; ++trial) {
    const float v = static_cast<float>(inside(rng));
    const long double exact = std::log2(static_cast<long double>(v));
    expectExactlyWithin(log2(Interval::point(v)), exact, 0x1p-21L, "log2", v);
  }
  for (int trial = 0; trial < 2000; ++trial) {
    const double e = logOutside(rng);
    if (std::fabs(e) <= 1.0) continue;
    const float v = static_cast<float>(std::exp2(e));
    if (v >= 0.5f && v <= 2.0f) continue;
    const long double exact = std::log2(static_cast<long double>(v));
    expectExactlyWithin(log2(Interval::point(v)), exact, 3.0L * ulpOf(exact), "log2", v);
  }
  EXPECT_TRUE(log2(Interval::point(0.0f)).undefined);
}

TEST(OracleIntervalBuiltins, PowContainsTheExactPowerAndIsUndefinedForANegativeBase) {
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> base(0.001, 4.0);
  std::uniform_real_distribution<double> exponent(0.5, 8.0);
  for (int trial = 0; trial < 2000; ++trial) {
    const float x = static_cast<float>(base(rng));
    const float y = static_cast<float>(exponent(rng));
    const Interval r = pow(Interval::point(x), Interval::point(y));
    ASSERT_TRUE(contains(r, static_cast<double>(std::pow(static_cast<long double>(x), y))))
        << x << " " << y;
    ASSERT_TRUE(contains(r, std::pow(x, y))) << x << " " << y;
  }
  EXPECT_TRUE(pow(Interval(-1e-7, 0.5), Interval::point(5.0f)).undefined);
  EXPECT_TRUE(pow(Interval::point(-2.0f), Interval::point(2.0f)).undefined);
  EXPECT_TRUE(pow(Interval::point(0.0f), Interval::point(0.0f)).undefined);
  // Inherited from exp2(y * log2(x)): log2(0) has no precision, so a base
  // that may be 0 leaves pow open (tests/oracle/oracle_audit_test.cpp).
  EXPECT_TRUE(pow(Interval::point(0.0f), Interval::point(5.0f)).undefined);
  EXPECT_TRUE(pow(Interval(0.0, 0.5), Interval::point(5.0f)).undefined);
  const Interval fromEighth = pow(Interval(0.125, 0.5), Interval::point(5.0f));
  EXPECT_TRUE(contains(fromEighth, 0x1p-15f));
  EXPECT_TRUE(contains(fromEighth, 0.03125f));
  EXPECT_FALSE(contains(fromEighth, 0.0313f));
}

TEST(OracleIntervalBuiltins, MaxAndMinAreExact) {
  const Interval m = max(Interval(-1.0, 2.0), Interval(0.0, 0.0));
  EXPECT_EQ(m.lo, 0.0);
  EXPECT_EQ(m.hi, 2.0);
  const Interval n = min(Interval(-1.0, 2.0), Interval(0.0, 0.0));
  EXPECT_EQ(n.lo, -1.0);
  EXPECT_EQ(n.hi, 0.0);
}

// Every summation order, each with and without fused multiply-adds.
std::vector<float> everyOrder(std::array<float, 4> a, std::array<float, 4> b, int n) {
  std::vector<int> order(n);
  for (int k = 0; k < n; ++k) order[k] = k;
  std::vector<float> results;
  do {
    float plain = a[order[0]] * b[order[0]];
    float fused = plain;
    for (int k = 1; k < n; ++k) {
      plain = plain + a[order[k]] * b[order[k]];
      fused = std::fma(a[order[k]], b[order[k]], fused);
    }
    results.push_back(plain);
    results.push_back(fused);
  } while (std::next_permutation(order.begin(), order.end()));
  // Pairwise: (a0 b0 + a1 b1) + (a2 b2 + a3 b3).
  if (n == 4) results.push_back((a[0] * b[0] + a[1] * b[1]) + (a[2] * b[2] + a[3] * b[3]));
  return results;
}

TEST(OracleIntervalBuiltins, SumOfProductsHoldsEveryOrderAndFusion) {
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<float> value(-1.0f, 1.0f);
  for (int n = 2; n <= 4; ++n) {
    for (int trial = 0; trial < 3000; ++trial) {
      std::array<float, 4> a{}, b{};
      std::array<Interval, 4> ia, ib;
      long double exact = 0.0L;
      double magnitude = 0.0;
      for (int k = 0; k < n; ++k) {
        a[k] = value(rng);
        b[k] = value(rng);
        ia[k] = Interval::point(a[k]);
        ib[k] = Interval::point(b[k]);
        exact += static_cast<long double>(a[k]) * b[k];
        magnitude += std::fabs(double(a[k]) * b[k]);
      }
      const Interval r = sumOfProducts(std::span<const Interval>(ia.data(), n),
                                       std::span<const Interval>(ib.data(), n));
      ASSERT_TRUE(contains(r, static_cast<double>(exact)));
      for (float computed : everyOrder(a, b, n)) ASSERT_TRUE(contains(r, computed)) << "n=" << n;
      // Not vacuous: within gamma_n * sum |a_i b_i| (and the flush term) of
      // the exact value on each side.
      const double gamma = n * 0x1p-23 / (1 - n * 0x1p-23);
      ASSERT_LE(width(r),
                2 * gamma * magnitude * (1 + 0x1p-20) + 2 * ulp(static_cast<double>(exact)));
    }
  }
}

}  // namespace
}  // namespace snell
