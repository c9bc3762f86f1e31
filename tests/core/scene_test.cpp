#include "core/scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

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
  const Scene scene = makeScene("sphere");
  const Value& m = scene.values.at("texture_matrix");
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

// Every triangle of a drawing scene is counter-clockwise seen from outside:
// its geometric normal agrees with the vertex normals.
TEST(Scene, DrawingScenesFaceOutward) {
  for (const char* name : {"sphere", "torus"}) {
    const Scene s = makeScene(name);
    ASSERT_TRUE(s.draws()) << name;
    ASSERT_EQ(s.indices.size() % 3, 0u);
    const auto& p = s.attributes.at("position").data;
    const auto& n = s.attributes.at("normal").data;
    std::size_t inward = 0;
    for (std::size_t k = 0; k < s.indices.size(); k += 3) {
      const std::uint32_t a = s.indices[k], b = s.indices[k + 1], c = s.indices[k + 2];
      double e1[3], e2[3];
      for (int i = 0; i < 3; ++i) {
        e1[i] = double(p[b * 4 + i]) - p[a * 4 + i];
        e2[i] = double(p[c * 4 + i]) - p[a * 4 + i];
      }
      const double g[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                           e1[0] * e2[1] - e1[1] * e2[0]};
      const double along = g[0] * n[a * 3] + g[1] * n[a * 3 + 1] + g[2] * n[a * 3 + 2];
      inward += along <= 0;
    }
    EXPECT_EQ(inward, 0u) << name;
  }
}

TEST(Scene, ScenesAreReadFromData) {
  const Scene torus = makeScene("torus");
  EXPECT_EQ(torus.width, 256);
  EXPECT_EQ(torus.vertexCount, 65u * 33u);
  EXPECT_FALSE(makeScene("sweep").draws());
}

TEST(Scene, BrokenSceneFileNamesFileAndLine) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / "snell-scene-test";
  fs::create_directories(dir);
  std::ofstream(dir / "bad.toml") << "[geometry]\nshape = \"cube\"\n[camera]\n";
  try {
    makeScene("bad", {dir});
    FAIL();
  } catch (const UsageError& error) {
    EXPECT_NE(std::string(error.what()).find("bad.toml:2: unknown shape `cube`"), std::string::npos)
        << error.what();
  }
  fs::remove_all(dir);
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

namespace snell {
namespace {

// The full-screen pass covers every pixel centre with one triangle, and
// gives Shadertoy's iResolution as the image size.
TEST(Scene, FullscreenCoversTheViewportAndGivesTheResolution) {
  const Scene s = makeScene("fullscreen");
  ASSERT_TRUE(s.draws());
  EXPECT_EQ(s.indices.size(), 3u);
  const std::vector<float>& p = s.attributes.at("position").data;
  // Clip-space corners (-1,-1), (3,-1), (-1,3): the triangle's hypotenuse
  // x + y = 2 lies outside the square [-1, 1]^2, so all of it is covered.
  EXPECT_EQ((std::vector<float>{p[0], p[1], p[4], p[5], p[8], p[9]}),
            (std::vector<float>{-1, -1, 3, -1, -1, 3}));
  const Value& resolution = s.values.at("resolution");
  EXPECT_EQ(resolution.type, ValueType::Vec3);
  EXPECT_EQ(resolution.data, (std::vector<float>{static_cast<float>(s.width),
                                                 static_cast<float>(s.height), 1.0f}));
}

}  // namespace
}  // namespace snell
