// The camera semantics that tutorials and engines pass separately (view,
// view_projection, the world-space normal matrix) agree with the combined
// ones the scenes always gave, so a shader written either way sees the same
// transform up to float rounding.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>

#include "core/scene.h"

namespace snell {
namespace {

using Mat4f = std::array<double, 16>;

Mat4f mat4(const Scene& scene, const std::string& name) {
  const Value& v = scene.values.at(name);
  EXPECT_EQ(v.type, ValueType::Mat4) << name;
  Mat4f m{};
  for (int k = 0; k < 16; ++k) m[k] = v.data.at(k);
  return m;
}

Mat4f times(const Mat4f& a, const Mat4f& b) {
  Mat4f out{};
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      for (int k = 0; k < 4; ++k) out[c * 4 + r] += a[k * 4 + r] * b[c * 4 + k];
  return out;
}

// Largest element difference relative to the larger matrix's largest element.
double relativeDifference(const Mat4f& a, const Mat4f& b) {
  double diff = 0, scale = 0;
  for (int k = 0; k < 16; ++k) {
    diff = std::max(diff, std::abs(a[k] - b[k]));
    scale = std::max({scale, std::abs(a[k]), std::abs(b[k])});
  }
  return diff / scale;
}

class SceneConventions : public ::testing::TestWithParam<const char*> {};

TEST_P(SceneConventions, SeparateMatricesComposeToTheCombinedOnes) {
  const Scene scene = makeScene(GetParam());
  const Mat4f model = mat4(scene, "model"), view = mat4(scene, "view");
  const Mat4f projection = mat4(scene, "projection");
  // Each stored matrix is rounded to float once: products of the rounded
  // factors differ from the rounded product by a few float ulps.
  constexpr double kFloatRounding = 1e-6;
  EXPECT_LT(relativeDifference(times(view, model), mat4(scene, "modelview")), kFloatRounding);
  EXPECT_LT(relativeDifference(times(projection, view), mat4(scene, "view_projection")),
            kFloatRounding);
  EXPECT_LT(relativeDifference(times(mat4(scene, "view_projection"), model),
                               mat4(scene, "modelview_projection")),
            kFloatRounding);
}

TEST_P(SceneConventions, ModelNormalMatrixIsTheInverseTransposeOfModel) {
  const Scene scene = makeScene(GetParam());
  const Value& n = scene.values.at("model_normal_matrix");
  ASSERT_EQ(n.type, ValueType::Mat3);
  const Mat4f model = mat4(scene, "model");
  // transpose(inverse(M)) * transpose(M) = I for the upper 3x3: column c of
  // N dotted with column k of M is the Kronecker delta.
  for (int c = 0; c < 3; ++c)
    for (int k = 0; k < 3; ++k) {
      double dot = 0;
      for (int r = 0; r < 3; ++r) dot += n.data[c * 3 + r] * model[k * 4 + r];
      EXPECT_NEAR(dot, c == k ? 1.0 : 0.0, 1e-6) << c << "," << k;
    }
}

// On the sphere the model turns and the camera looks from off-axis, so a
// shader bound to the wrong one of two look-alike semantics shows.
TEST(SceneConventionsSphere, LookAlikeSemanticsDiffer) {
  const Scene scene = makeScene("sphere");
  EXPECT_GT(relativeDifference(mat4(scene, "view"), mat4(scene, "modelview")), 1e-3);
  EXPECT_GT(relativeDifference(mat4(scene, "view_projection"), mat4(scene, "modelview_projection")),
            1e-3);
  EXPECT_NE(scene.values.at("normal_matrix").data, scene.values.at("model_normal_matrix").data);
}

INSTANTIATE_TEST_SUITE_P(Scenes, SceneConventions,
                         ::testing::Values("sphere", "torus", "sweep", "fullscreen"));

}  // namespace
}  // namespace snell
