#include "core/environment.h"

#include <gtest/gtest.h>

#include <cmath>

namespace snell {
namespace {

TEST(Environment, NeighbourStepStaysWithinTheBoundTheImageToleranceUses) {
  // shaders/orange-book/*/manifest.toml derive their image tolerance from 0.05.
  const double step = largestNeighbourStep(makeEnvironment());
  EXPECT_LE(step, 0.05);
  EXPECT_GT(step, 0.0);
  RecordProperty("largest_neighbour_step", std::to_string(step));
}

TEST(Environment, EachFaceIsDistinct) {
  const CubeMap map = makeEnvironment();
  const int centre = (map.size / 2 * map.size + map.size / 2) * 4;
  for (int a = 0; a < 6; ++a)
    for (int b = a + 1; b < 6; ++b) {
      double difference = 0;
      for (int c = 0; c < 3; ++c)
        difference = std::max(
            difference, double(std::abs(map.faces[a][centre + c] - map.faces[b][centre + c])));
      EXPECT_GT(difference, 0.3) << a << " " << b;
    }
}

TEST(Environment, ContinuousAcrossFaceEdges) {
  // The texel of +X at its s = 1 edge (direction toward -Z) and the texel of
  // -Z at its s = 0 edge meet at the same edge: their colours must be close.
  const CubeMap map = makeEnvironment();
  const int n = map.size;
  for (int j = 0; j < n; ++j) {
    const float* plusX = &map.faces[0][(j * n + (n - 1)) * 4];
    const float* minusZ = &map.faces[5][(j * n + 0) * 4];
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(plusX[c], minusZ[c], 0.05) << j;
  }
}

TEST(Environment, GridLinesAreVisible) {
  const CubeMap map = makeEnvironment();
  const int n = map.size, row = n / 2 + 5;  // off the centre line
  // Along a row, the colour rises where the grid line at s = 1/8 crosses.
  const float onLine = map.faces[4][(row * n + n / 8) * 4 + 1];
  const float between = map.faces[4][(row * n + n / 8 + n / 16) * 4 + 1];
  EXPECT_GT(onLine - between, 0.05);
}

TEST(Environment, SharedIsMadeOncePerSizeAndEqualsAFreshOne) {
  const std::shared_ptr<const CubeMap> first = sharedEnvironment(32);
  EXPECT_EQ(sharedEnvironment(32).get(), first.get());
  const std::shared_ptr<const CubeMap> other = sharedEnvironment(16);
  EXPECT_NE(other.get(), first.get());
  EXPECT_EQ(other->size, 16);
  const CubeMap fresh = makeEnvironment(32);
  ASSERT_EQ(first->size, 32);
  for (int f = 0; f < 6; ++f) EXPECT_EQ(first->faces[f], fresh.faces[f]) << f;
}

}  // namespace
}  // namespace snell
