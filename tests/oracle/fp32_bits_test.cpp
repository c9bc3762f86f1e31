// The oracle's fast fp32 grid functions (oracle/fp32_bits.h, on the IEEE
// encodings) and its tabulated gamma(k) (oracle/interval_region_bounds.h)
// against straightforward formulations through libm (nextafter, frexp,
// ldexp) and the plain formula: they must agree bit for bit, on edge inputs
// (zeros, denormals, the float range's ends, powers of two and their
// neighbours, halfway points, infinities, NaN) and on random ones. The
// comparator is shown to fail on a deliberately wrong function.
#include "oracle/fp32_bits.h"

#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "oracle/interval_region_bounds.h"

namespace snell {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr float kInfF = std::numeric_limits<float>::infinity();

// ---- the reference formulations (libm) ----

double refGapAbove(double x) {
  x = std::fabs(x);
  if (std::isnan(x)) return x;
  if (x < kFp32MinNormal) return kFp32MinDenormal;
  if (x > kFp32Max) return 0x1p104;
  int exponent = 0;
  std::frexp(x, &exponent);
  return std::ldexp(1.0, exponent - 1 - 23);
}

double refUlp(double x) {
  const double gap = refGapAbove(x);
  x = std::fabs(x);
  int exponent = 0;
  const bool powerOfTwo = x > kFp32MinNormal && x <= kFp32Max && std::frexp(x, &exponent) == 0.5;
  return powerOfTwo ? gap * 0.5 : gap;
}

double refFloatAtOrBelow(double x) {
  if (std::isnan(x) || std::isinf(x)) return x;
  if (x > kFp32Max) return kFp32Max;
  if (x < -kFp32Max) return -kInf;
  const float nearest = static_cast<float>(x);
  if (static_cast<double>(nearest) <= x) return nearest;
  return std::nextafter(nearest, -kInfF);
}

double refFloatAtOrAbove(double x) {
  if (std::isnan(x) || std::isinf(x)) return x;
  if (x > kFp32Max) return kInf;
  if (x < -kFp32Max) return -kFp32Max;
  const float nearest = static_cast<float>(x);
  if (static_cast<double>(nearest) >= x) return nearest;
  return std::nextafter(nearest, kInfF);
}

bool refIsPositivePowerOfTwo(double x) {
  int exponent = 0;
  return x > 0 && std::frexp(x, &exponent) == 0.5;
}

double refPowerOfTwoAbove(double x) {
  int exponent = 0;
  std::frexp(x, &exponent);
  return std::ldexp(1.0, exponent);
}

double refGamma(int k) {
  if (k <= 0) return 0.0;
  const double ku = k * 0x1p-23;
  const double g = ku / (1.0 - ku);
  return g + std::fabs(g) * 0x1p-51;
}

// ---- inputs ----

std::vector<double> edgeInputs() {
  std::vector<double> v = {0.0,
                           std::numeric_limits<double>::denorm_min(),
                           std::numeric_limits<double>::min(),
                           std::numeric_limits<double>::max(),
                           kInf,
                           std::numeric_limits<double>::quiet_NaN(),
                           kFp32MinDenormal,
                           kFp32MinNormal,
                           0x1p-125,
                           kFp32Max,
                           0x1.fffffefffffffp127,  // rounds to FLT_MAX
                           0x1.ffffffp127,         // halfway to 2^128
                           0x1p128,
                           0x1p104,
                           1.0 / 3.0,
                           0.66};
  for (int e = -1074; e <= 1023; ++e) v.push_back(std::ldexp(1.0, e));
  // Halfway points and their neighbours between floats, normal and denormal.
  for (float f : {1.0f, 1.5f, 0x1p-126f, 0x1p-140f, 0x1.fffffep127f, 3.0e-39f, 12345.678f}) {
    const double next = std::nextafter(f, kInfF);
    v.push_back((static_cast<double>(f) + next) / 2);
  }
  const std::size_t base = v.size();
  for (std::size_t i = 0; i < base; ++i) {
    v.push_back(std::nextafter(v[i], kInf));
    v.push_back(std::nextafter(v[i], -kInf));
    v.push_back(static_cast<float>(v[i]));
  }
  const std::size_t withNeighbours = v.size();
  for (std::size_t i = 0; i < withNeighbours; ++i) v.push_back(-v[i]);
  return v;
}

std::vector<double> randomInputs() {
  std::mt19937_64 rng(2024);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-160, 140);
  std::vector<double> v;
  for (int i = 0; i < 200000; ++i) {
    v.push_back(std::bit_cast<double>(rng()));          // any encoding
    v.push_back(std::ldexp(unit(rng), exponent(rng)));  // around the float range
    v.push_back(static_cast<float>(std::ldexp(unit(rng), exponent(rng))));  // floats
  }
  return v;
}

// ---- the comparator ----

// Same bits, or both NaN (a NaN's payload is no result of the oracle's).
bool sameDouble(double a, double b) {
  if (std::isnan(a) && std::isnan(b)) return true;
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

// One failure naming every input on which `fast` and `reference` differ
// (the first 5 of them).
void expectSame(const std::string& name, const std::function<double(double)>& fast,
                const std::function<double(double)>& reference, const std::vector<double>& inputs) {
  int mismatches = 0;
  std::ostringstream first;
  for (double x : inputs) {
    const double got = fast(x), want = reference(x);
    if (sameDouble(got, want)) continue;
    if (++mismatches <= 5)
      first << "\n  " << name << "(" << std::hexfloat << x << ") = " << got << ", reference "
            << want;
  }
  if (mismatches > 0)
    ADD_FAILURE() << name << " differs from its reference on " << mismatches
                  << " inputs:" << first.str();
}

void expectSameEverywhere(const std::string& name, const std::function<double(double)>& fast,
                          const std::function<double(double)>& reference) {
  expectSame(name + " (edges)", fast, reference, edgeInputs());
  expectSame(name + " (random)", fast, reference, randomInputs());
}

TEST(Fp32Bits, GapAboveAndUlpAreLibmsBitForBit) {
  expectSameEverywhere("gapAbove", fp32_bits::gapAbove, refGapAbove);
  expectSameEverywhere("ulp", fp32_bits::ulp, refUlp);
}

TEST(Fp32Bits, FloatNeighboursAreLibmsBitForBit) {
  expectSameEverywhere("floatAtOrBelow", fp32_bits::floatAtOrBelow, refFloatAtOrBelow);
  expectSameEverywhere("floatAtOrAbove", fp32_bits::floatAtOrAbove, refFloatAtOrAbove);
}

TEST(Fp32Bits, DoubleStepsAreNextafterBitForBit) {
  expectSameEverywhere("nextUp", fp32_bits::nextUp,
                       [](double x) { return std::nextafter(x, kInf); });
  expectSameEverywhere("nextDown", fp32_bits::nextDown,
                       [](double x) { return std::nextafter(x, -kInf); });
}

TEST(Fp32Bits, FloatStepsAreNextafterBitForBit) {
  // Over every float that is not NaN: the inputs' float roundings.
  const auto asFloat = [](double x) {
    // Past the float range the cast is not defined: take the infinity.
    if (std::fabs(x) > kFp32Max) return x > 0 ? kInfF : -kInfF;
    return static_cast<float>(x);
  };
  expectSameEverywhere(
      "nextUpFloat",
      [&](double x) { return std::isnan(x) ? x : double{fp32_bits::nextUpFloat(asFloat(x))}; },
      [&](double x) { return std::isnan(x) ? x : double{std::nextafter(asFloat(x), kInfF)}; });
  expectSameEverywhere(
      "nextDownFloat",
      [&](double x) { return std::isnan(x) ? x : double{fp32_bits::nextDownFloat(asFloat(x))}; },
      [&](double x) { return std::isnan(x) ? x : double{std::nextafter(asFloat(x), -kInfF)}; });
}

TEST(Fp32Bits, PowersOfTwoAreFrexpsBitForBit) {
  expectSameEverywhere(
      "isPositivePowerOfTwo",
      [](double x) { return fp32_bits::isPositivePowerOfTwo(x) ? 1.0 : 0.0; },
      [](double x) { return refIsPositivePowerOfTwo(x) ? 1.0 : 0.0; });
  // powerOfTwoAbove is for normal x > 0 (lowestWithinUlps calls it at
  // x >= 2^-125).
  const auto normalPositive = [](double x) {
    return std::isfinite(x) && std::fabs(x) >= std::numeric_limits<double>::min();
  };
  expectSameEverywhere(
      "powerOfTwoAbove",
      [&](double x) { return normalPositive(x) ? fp32_bits::powerOfTwoAbove(std::fabs(x)) : 0.0; },
      [&](double x) { return normalPositive(x) ? refPowerOfTwoAbove(std::fabs(x)) : 0.0; });
}

TEST(Fp32Bits, TabulatedGammaIsTheFormulaBitForBit) {
  for (int k = -2; k < 4 * region_detail::kGammaTableSize; ++k)
    EXPECT_TRUE(sameDouble(gammaBound(k), refGamma(k))) << "k = " << k;
}

TEST(Fp32Bits, ZeroOrNormalFloatIsTheConversionsVerdict) {
  expectSameEverywhere(
      "isZeroOrNormalFloat", [](double x) { return fp32_bits::isZeroOrNormalFloat(x) ? 1.0 : 0.0; },
      [](double x) {
        const double a = std::fabs(x);
        const bool normal = a >= kFp32MinNormal && a <= kFp32Max;
        // The cast is defined inside the float range only.
        return x == 0.0 || (normal && static_cast<double>(static_cast<float>(x)) == x) ? 1.0 : 0.0;
      });
}

// The regions' margin is one multiplication: the same bits as x + |x| 2^-51
// wherever x * 2^-51 is exact (x = 0 or x >= 2^-971), and never below x.
TEST(Fp32Bits, TheRegionMarginIsTheAdditionBitForBit) {
  std::vector<double> exact;
  for (const std::vector<double>& inputs : {edgeInputs(), randomInputs()}) {
    for (const double x : inputs) {
      const double a = std::fabs(x);
      if (a == 0.0 || a >= 0x1p-971) exact.push_back(a);
      if (!std::isnan(a)) {
        EXPECT_GE(region_detail::up(a), a) << std::hexfloat << a;
      }
    }
  }
  expectSame("region_detail::up", region_detail::up, [](double a) { return a + a * 0x1p-51; },
             exact);
}

// The comparison above fails on a wrong value: a gap that is off at powers
// of two only (the gap below instead of above), and a float neighbour off by
// one float on negative inputs only.
TEST(Fp32Bits, TheComparisonFailsOnAWrongFunction) {
  const auto gapBelowAtPowers = [](double x) {
    const double gap = fp32_bits::gapAbove(x);
    return refIsPositivePowerOfTwo(std::fabs(x)) && std::fabs(x) > kFp32MinNormal ? gap / 2 : gap;
  };
  EXPECT_NONFATAL_FAILURE(expectSame("gapAbove", gapBelowAtPowers, refGapAbove, edgeInputs()),
                          "differs from its reference");
  const auto oneFloatLowOnNegatives = [](double x) {
    const double r = fp32_bits::floatAtOrBelow(x);
    return x < 0.0 && x > -kFp32Max ? double{fp32_bits::nextDownFloat(static_cast<float>(r))} : r;
  };
  EXPECT_NONFATAL_FAILURE(
      expectSame("floatAtOrBelow", oneFloatLowOnNegatives, refFloatAtOrBelow, randomInputs()),
      "differs from its reference");
  // A NaN where the reference gives a number is a difference too.
  EXPECT_FALSE(sameDouble(std::numeric_limits<double>::quiet_NaN(), 1.0));
  EXPECT_FALSE(sameDouble(0.0, -0.0));
}

}  // namespace
}  // namespace snell
