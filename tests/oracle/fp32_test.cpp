// The fp32 grid helpers every interval bound goes through.
#include "oracle/fp32.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace snell {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Harrison's ULP (the Vulkan spec's and dEQP's): the smallest gap between
// floats a <= x <= b, so at an exact power of two the gap below.
TEST(OracleFp32, UlpIsTheGapBetweenFloatsOfTheBinadeAndBelowAPowerOfTwo) {
  EXPECT_EQ(ulp(1.0), 0x1p-24);
  EXPECT_EQ(ulp(1.0000001), 0x1p-23);
  EXPECT_EQ(ulp(1.9999), 0x1p-23);
  EXPECT_EQ(ulp(0.75), 0x1p-24);
  EXPECT_EQ(ulp(-3.0), 0x1p-22);
  EXPECT_EQ(ulp(-4.0), 0x1p-22);
  EXPECT_EQ(ulp(0x1p-126), 0x1p-149);  // the gap below is a denormal gap
  EXPECT_EQ(ulp(0x1p-130), 0x1p-149);  // denormals
  EXPECT_EQ(ulp(0.0), 0x1p-149);
  EXPECT_EQ(ulp(0x1.fffffep127), 0x1p104);
}

TEST(OracleFp32, UlpMatchesTheSmallestDistanceToANeighbouringFloat) {
  for (float f : {1.0f, 1.1f, 3.0e-5f, 7.5e20f, 1.0e-39f, -2.5f, 0.5f, 1024.0f}) {
    const float a = std::fabs(f);
    const float next = std::nextafter(a, std::numeric_limits<float>::infinity());
    const float previous = std::nextafter(a, 0.0f);
    const double smallest = std::min(double(next) - double(a), double(a) - double(previous));
    EXPECT_EQ(ulp(f), smallest) << f;
  }
}

TEST(OracleFp32, GapAboveIsTheGapOfTheBinade) {
  EXPECT_EQ(gapAbove(1.0), 0x1p-23);
  EXPECT_EQ(gapAbove(0.75), 0x1p-24);
  EXPECT_EQ(gapAbove(0x1p-130), 0x1p-149);
  EXPECT_EQ(gapAbove(0x1.fffffep127), 0x1p104);
}

TEST(OracleFp32, BracketsARealBetweenTheTwoFloatsAroundIt) {
  EXPECT_EQ(floatAtOrBelow(1.0 + 0x1p-30), 1.0);
  EXPECT_EQ(floatAtOrAbove(1.0 + 0x1p-30), 1.0 + 0x1p-23);
  EXPECT_EQ(floatAtOrBelow(-1.0 - 0x1p-30), -1.0 - 0x1p-23);
  EXPECT_EQ(floatAtOrAbove(-1.0 - 0x1p-30), -1.0);
  // Just below a power of two the gap is half as wide.
  EXPECT_EQ(floatAtOrBelow(1.0 - 0x1p-30), 1.0 - 0x1p-24);
  EXPECT_EQ(floatAtOrBelow(0.5), 0.5);
  EXPECT_EQ(floatAtOrAbove(0.5), 0.5);
}

TEST(OracleFp32, BeyondTheFloatRangeLieTheInfinities) {
  EXPECT_EQ(floatAtOrAbove(1e39), kInf);
  EXPECT_EQ(floatAtOrBelow(1e39), 0x1.fffffep127);
  EXPECT_EQ(floatAtOrBelow(-1e39), -kInf);
  EXPECT_EQ(floatAtOrBelow(kInf), kInf);
  EXPECT_TRUE(isFloat(kInf));
  EXPECT_TRUE(isFloat(0.1f));
  EXPECT_FALSE(isFloat(0.1));
  EXPECT_FALSE(isFloat(1e39));
}

}  // namespace
}  // namespace snell
