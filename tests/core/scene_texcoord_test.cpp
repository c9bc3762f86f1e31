// The per-vertex texture coordinate and the decal that drawing scenes give
// (scene.texcoord, scene.decal).
#include <gtest/gtest.h>

#include "core/scene.h"

namespace snell {
namespace {

TEST(SceneTexcoord, SphereAndTorusGiveTheGridsUVInZeroOne) {
  for (const char* name : {"sphere", "torus"}) {
    const Scene s = makeScene(name);
    const AttributeStream& texcoord = s.attributes.at("texcoord");
    ASSERT_EQ(texcoord.components, 2) << name;
    ASSERT_EQ(texcoord.vertexCount(), s.vertexCount) << name;
    float lowest = 1, highest = 0;
    for (float c : texcoord.data) {
      lowest = std::min(lowest, c);
      highest = std::max(highest, c);
    }
    // The seam column and the last row are there twice, at 0 and at 1.
    EXPECT_EQ(lowest, 0.0f) << name;
    EXPECT_EQ(highest, 1.0f) << name;
  }
}

TEST(SceneTexcoord, NoTriangleWrapsAroundTheSeam) {
  // Every triangle's u and v span at most one grid cell: a triangle from
  // u = 0.99 to u = 0 would smear the whole decal across it.
  for (const char* name : {"sphere", "torus"}) {
    const Scene s = makeScene(name);
    const std::vector<float>& uv = s.attributes.at("texcoord").data;
    for (std::size_t k = 0; k < s.indices.size(); k += 3)
      for (int c = 0; c < 2; ++c) {
        float lo = 1, hi = 0;
        for (int v = 0; v < 3; ++v) {
          const float x =
              uv[s.indices[k + static_cast<std::size_t>(v)] * 2 + static_cast<std::size_t>(c)];
          lo = std::min(lo, x);
          hi = std::max(hi, x);
        }
        ASSERT_LE(hi - lo, 0.1f) << name << " triangle " << k / 3;
      }
  }
}

TEST(SceneTexcoord, TheSweepHasNoSurfaceAndGivesNone) {
  EXPECT_EQ(makeScene("sweep").attributes.count("texcoord"), 0u);
}

TEST(SceneTexcoord, DrawingScenesListAndHoldTheDecal) {
  const Scene s = makeScene("sphere");
  EXPECT_NE(std::find(s.samplers.begin(), s.samplers.end(), "decal"), s.samplers.end());
  ASSERT_TRUE(s.decal);
  EXPECT_EQ(s.decal->width, 128);
  EXPECT_FALSE(makeScene("sweep").decal);
}

}  // namespace
}  // namespace snell
