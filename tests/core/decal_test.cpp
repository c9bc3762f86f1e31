#include "core/decal.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

namespace snell {
namespace {

TEST(Decal, NeighbourStepStaysWithinTheBoundTheImageToleranceUses) {
  // shaders/cg-tutorial/c7e4f-refraction/manifest.toml derives its image
  // tolerance from 0.05, wrap-around neighbours included (REPEAT).
  const double step = largestNeighbourStep(makeDecal());
  EXPECT_LE(step, 0.05);
  EXPECT_GT(step, 0.0);
  RecordProperty("largest_neighbour_step", std::to_string(step));
}

TEST(Decal, IsRgba128WithOpaqueAlphaAndChannelsInsideZeroOne) {
  const Image decal = makeDecal();
  ASSERT_EQ(decal.width, 128);
  ASSERT_EQ(decal.height, 128);
  ASSERT_EQ(decal.pixels.size(), 128u * 128u * 4u);
  for (std::size_t k = 0; k < decal.pixels.size(); ++k) {
    if (k % 4 == 3) {
      EXPECT_EQ(decal.pixels[k], 1.0f);
    } else {
      EXPECT_GE(decal.pixels[k], 0.0f);
      EXPECT_LE(decal.pixels[k], 1.0f);
    }
  }
}

TEST(Decal, SameBitsEveryTime) {
  const Image a = makeDecal(), b = makeDecal();
  EXPECT_EQ(std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(float)), 0);
}

TEST(Decal, GridLinesAreVisibleInBothDirections) {
  const Image decal = makeDecal();
  const int n = decal.width, off = n / 16;  // half way between two lines
  // Red along a row crosses the line at s = 1/4; green along a column the one at t = 1/4.
  EXPECT_GT(decal.at(n / 4 + off, n / 2 + off)[0] - decal.at(n / 4, n / 2 + off)[0], 0.05);
  EXPECT_GT(decal.at(n / 2 + off, n / 4 + off)[1] - decal.at(n / 2 + off, n / 4)[1], 0.05);
}

TEST(Decal, SwappingSAndTChangesTheColour) {
  const Image decal = makeDecal();
  const int a = 20, b = 90;  // away from the grid lines
  double difference = 0;
  for (int c = 0; c < 3; ++c)
    difference = std::max(difference, double(std::abs(decal.at(a, b)[c] - decal.at(b, a)[c])));
  EXPECT_GT(difference, 0.1);
}

}  // namespace
}  // namespace snell
