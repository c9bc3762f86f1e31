#include "core/scene.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/errors.h"

namespace snell {
namespace {

double incidenceDegrees(const Scene& s, std::size_t k) {
  // Sweep eye space equals model space: i = normalize(position), n = normal.
  const float* p = &s.attributes.at("position").data[k * 4];
  const float* n = &s.attributes.at("normal").data[k * 3];
  double pl = 0, nl = 0, d = 0;
  for (int c = 0; c < 3; ++c) {
    pl += double(p[c]) * p[c];
    nl += double(n[c]) * n[c];
    d += -double(p[c]) * n[c];
  }
  return std::acos(d / std::sqrt(pl * nl)) * 180 / M_PI;
}

TEST(Scene, SphereHasThousandsOfUnitNormals) {
  const Scene s = makeScene("sphere");
  EXPECT_GT(s.vertexCount, 4000u);
  const auto& normal = s.attributes.at("normal");
  ASSERT_EQ(normal.vertexCount(), s.vertexCount);
  for (std::size_t k = 0; k < s.vertexCount; ++k) {
    const float* n = &normal.data[k * 3];
    EXPECT_NEAR(std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]), 1.0, 1e-6);
  }
}

TEST(Scene, TextureMatrixRotatesAndTranslates) {
  const Value& m = makeScene("sphere").values.at("texture_matrix");
  ASSERT_EQ(m.type, ValueType::Mat4);
  EXPECT_NE(m.data[12], 0.0f);  // translation column is used by vec4(Refract, 1.0)
  EXPECT_NE(m.data[1], 0.0f);   // not diagonal: a rotation
}

TEST(Scene, SweepCoversNormalToGrazingAndPast) {
  const Scene s = makeScene("sweep");
  double lowest = 180, highest = 0;
  std::size_t nearGrazing = 0, past = 0;
  for (std::size_t k = 0; k < s.vertexCount; ++k) {
    const double a = incidenceDegrees(s, k);
    lowest = std::min(lowest, a);
    highest = std::max(highest, a);
    nearGrazing += (a > 89.0 && a <= 90.0);
    past += a > 90.0;
  }
  EXPECT_LT(lowest, 0.01);
  EXPECT_GT(highest, 95.0);
  EXPECT_GT(nearGrazing, 500u);
  EXPECT_GT(past, 500u);
}

TEST(Scene, SameFloatsEveryTime) {
  EXPECT_EQ(makeScene("sweep").attributes.at("normal").data,
            makeScene("sweep").attributes.at("normal").data);
}

TEST(Scene, UnknownSceneListsKnownOnes) {
  try {
    makeScene("teapot");
    FAIL();
  } catch (const UsageError& error) {
    EXPECT_NE(std::string(error.what()).find("sphere"), std::string::npos);
  }
}

}  // namespace
}  // namespace snell
