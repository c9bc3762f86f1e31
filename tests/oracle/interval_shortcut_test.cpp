// The oracle's shorter roads through Interval operations (an exact point
// times an exact point, ...) must give the general road's bits in every
// field: a shortcut changes how fast the interval is computed, never what
// it is.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "oracle/interval.h"
#include "oracle/interval_float_sets.h"
#include "oracle/precision_rules.h"

namespace snell {
namespace {

std::uint64_t bitsOf(double x) { return std::bit_cast<std::uint64_t>(x); }

// Every field, bit for bit (a -0 for a +0 is a difference).
std::vector<std::string> differences(const Interval& a, const Interval& b) {
  std::vector<std::string> found;
  const auto number = [&](const char* name, double x, double y) {
    if (bitsOf(x) != bitsOf(y))
      found.push_back(std::string(name) + ": " + std::to_string(x) + " vs " + std::to_string(y));
  };
  const auto whole = [&](const char* name, long x, long y) {
    if (x != y)
      found.push_back(std::string(name) + ": " + std::to_string(x) + " vs " + std::to_string(y));
  };
  number("lo", a.lo, b.lo);
  number("hi", a.hi, b.hi);
  number("idealLo", a.idealLo, b.idealLo);
  number("idealHi", a.idealHi, b.idealHi);
  number("err", a.err, b.err);
  number("folded", a.folded, b.folded);
  whole("undefined", a.undefined, b.undefined);
  whole("constant", a.constant, b.constant);
  whole("region.kind", static_cast<long>(a.region.kind), static_cast<long>(b.region.kind));
  number("region.mag", a.region.mag, b.region.mag);
  number("region.mag0", a.region.mag0, b.region.mag0);
  number("region.maxSub", a.region.maxSub, b.region.maxSub);
  whole("region.terms", a.region.terms, b.region.terms);
  whole("region.degree", a.region.degree, b.region.degree);
  whole("region.factors", a.region.factors, b.region.factors);
  whole("region.exactFactors", a.region.exactFactors, b.region.exactFactors);
  number("region.termRounding", a.region.termRounding, b.region.termRounding);
  number("region.termFlush", a.region.termFlush, b.region.termFlush);
  return found;
}

// Floats of every kind: zeros of both signs, denormals, the smallest
// normal, the largest float, powers of two, and random floats over the
// whole exponent range.
std::vector<float> floatsOfEveryKind() {
  std::vector<float> values = {0.0f,
                               -0.0f,
                               1.0f,
                               -1.0f,
                               2.0f,
                               0.5f,
                               3.0f,
                               0.1f,
                               -0.7f,
                               1e-45f,
                               -1e-45f,
                               1e-40f,
                               1.17549435e-38f,
                               -1.17549435e-38f,
                               1.2e-38f,
                               3.4028235e38f,
                               -3.4028235e38f,
                               1e19f,
                               1e-19f,
                               65504.0f,
                               1.0000001f,
                               0.99999994f};
  std::mt19937_64 rng(13);
  std::uniform_int_distribution<std::uint32_t> bits(0, 0x7f7fffffu);
  std::bernoulli_distribution negative;
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  for (int k = 0; k < 400; ++k) {
    const float f = std::bit_cast<float>(bits(rng));
    values.push_back(negative(rng) ? -f : f);
    values.push_back(unit(rng));
  }
  return values;
}

// The general road for a point: a constant takes it (an exact point is an
// input or a uniform), and is there the same value as the input, unless it
// is a power of two (a literal 2^n multiplies without rounding).
Interval onTheGeneralRoad(float value) {
  Interval v = Interval::point(value);
  v.constant = true;
  v.folded = value;
  return v;
}
bool isPowerOfTwo(float value) {
  int exponent = 0;
  return value != 0.0f && std::frexp(std::fabs(value), &exponent) == 0.5f;
}

TEST(IntervalShortcut, APointProductTakesTheGeneralRoadsBits) {
  const std::vector<float> values = floatsOfEveryKind();
  for (const PrecisionRules rules : {PrecisionRules::Glsl, PrecisionRules::Vulkan}) {
    const UsePrecisionRules applied(rules);
    int compared = 0;
    for (std::size_t i = 0; i < values.size(); i += 3) {
      for (std::size_t j = 0; j < values.size(); j += 5) {
        const float x = values[i];
        const float y = values[j];
        if (isPowerOfTwo(x) || std::fpclassify(x) == FP_SUBNORMAL) continue;
        const Interval shortcut = Interval::point(x) * Interval::point(y);
        const Interval general = onTheGeneralRoad(x) * Interval::point(y);
        const std::vector<std::string> found = differences(shortcut, general);
        ASSERT_TRUE(found.empty())
            << precisionRulesName(rules) << ": " << x << " * " << y << ": " << found.front();
        ++compared;
      }
    }
    EXPECT_GT(compared, 10000);
  }
}

// a * b's lower (low) or upper bound by the error-free transformation: the
// product, one double outward where the fma finds it inexact.
double outward(double a, double b, bool low) {
  const double p = a * b;
  const double error = std::isfinite(p) ? std::fma(a, b, -p) : 0.0;
  if (low) return error < 0.0 ? std::nextafter(p, -INFINITY) : p;
  return error > 0.0 ? std::nextafter(p, INFINITY) : p;
}

// exactProductRange takes a point's repeated products once: its bounds are
// those of all four products, each rounded outward where it is inexact.
TEST(IntervalShortcut, APointTimesARangeGivesTheFourProductsBounds) {
  const std::vector<float> values = floatsOfEveryKind();
  std::mt19937_64 rng(3);
  std::uniform_int_distribution<std::size_t> pick(0, values.size() - 1);
  for (int trial = 0; trial < 20000; ++trial) {
    const double point = values[pick(rng)];
    double lo = values[pick(rng)];
    double hi = values[pick(rng)];
    if (hi < lo) std::swap(lo, hi);
    for (const bool pointFirst : {true, false}) {
      const float_sets::Range got = pointFirst
                                        ? float_sets::exactProductRange(point, point, lo, hi)
                                        : float_sets::exactProductRange(lo, hi, point, point);
      double low = INFINITY;
      double high = -INFINITY;
      for (const double x : {lo, hi}) {
        low = std::min(low, outward(point, x, true));
        high = std::max(high, outward(point, x, false));
      }
      ASSERT_EQ(bitsOf(got.lo), bitsOf(low)) << point << " * [" << lo << ", " << hi << "]";
      ASSERT_EQ(bitsOf(got.hi), bitsOf(high)) << point << " * [" << lo << ", " << hi << "]";
    }
  }
}

// Two ranges whose ends are floats multiply exactly in double, so
// exactProductRange takes their four products as they are: the bounds are
// the error-free transformation's, bit for bit (signed zeros included), for
// floats of every kind and for ends that are not floats.
TEST(IntervalShortcut, FloatRangesGiveTheErrorFreeProductsBounds) {
  const std::vector<float> values = floatsOfEveryKind();
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<std::size_t> pick(0, values.size() - 1);
  std::bernoulli_distribution notAFloat(0.2);
  const auto end = [&] {
    const double x = values[pick(rng)];
    return notAFloat(rng) ? x * (1.0 + 0x1p-40) : x;
  };
  for (int trial = 0; trial < 100000; ++trial) {
    double alo = end(), ahi = end(), blo = end(), bhi = end();
    if (ahi < alo) std::swap(alo, ahi);
    if (bhi < blo) std::swap(blo, bhi);
    double low = INFINITY;
    double high = -INFINITY;
    bool nan = false;
    for (const double a : {alo, ahi})
      for (const double b : {blo, bhi}) {
        nan = nan || std::isnan(a * b);
        low = std::min(low, outward(a, b, true));
        high = std::max(high, outward(a, b, false));
      }
    const float_sets::Range got = float_sets::exactProductRange(alo, ahi, blo, bhi);
    const std::string where = "[" + std::to_string(alo) + ", " + std::to_string(ahi) + "] * [" +
                              std::to_string(blo) + ", " + std::to_string(bhi) + "]";
    if (nan) {
      ASSERT_TRUE(std::isnan(got.lo) && std::isnan(got.hi)) << where;
      continue;
    }
    ASSERT_EQ(bitsOf(got.lo), bitsOf(low)) << where;
    ASSERT_EQ(bitsOf(got.hi), bitsOf(high)) << where;
  }
}

// quotientRange takes a point's repeated quotients once: its bounds are the
// hull of each pair of ends divided alone.
TEST(IntervalShortcut, APointDividendOrDivisorGivesEveryPairsBounds) {
  const std::vector<float> values = floatsOfEveryKind();
  std::mt19937_64 rng(5);
  std::uniform_int_distribution<std::size_t> pick(0, values.size() - 1);
  for (int trial = 0; trial < 20000; ++trial) {
    const double point = values[pick(rng)];
    double lo = values[pick(rng)];
    double hi = values[pick(rng)];
    if (hi < lo) std::swap(lo, hi);
    if (lo <= 0.0 && hi >= 0.0) continue;  // a divisor that may be 0
    for (const bool pointDividend : {true, false}) {
      const auto alone = [&](double end) {
        return pointDividend ? float_sets::quotientRange(point, point, end, end)
                             : float_sets::quotientRange(end, end, point, point);
      };
      if (!pointDividend && point == 0.0) continue;
      const float_sets::Range got = pointDividend ? float_sets::quotientRange(point, point, lo, hi)
                                                  : float_sets::quotientRange(lo, hi, point, point);
      const float_sets::Range low = alone(lo);
      const float_sets::Range high = alone(hi);
      ASSERT_EQ(bitsOf(got.lo), bitsOf(std::min(low.lo, high.lo)))
          << pointDividend << " " << point << " [" << lo << ", " << hi << "]";
      ASSERT_EQ(bitsOf(got.hi), bitsOf(std::max(low.hi, high.hi)))
          << pointDividend << " " << point << " [" << lo << ", " << hi << "]";
    }
  }
}

}  // namespace
}  // namespace snell
