// The table of fixed-function built-ins and GL's derived state.
#include "core/legacy_builtins.h"

#include <gtest/gtest.h>

#include "core/camera_math.h"
#include "core/scene.h"

namespace snell {
namespace {

TEST(LegacyBuiltins, KnowsTheNamesManifestsBind) {
  const auto modelview = findLegacyBuiltin("gl_ModelViewMatrix");
  ASSERT_TRUE(modelview);
  EXPECT_EQ(modelview->kind, LegacyBuiltinKind::Matrix);
  EXPECT_EQ(modelview->type, ValueType::Mat4);

  const auto texture = findLegacyBuiltin("gl_TextureMatrix[7]");
  ASSERT_TRUE(texture);
  EXPECT_EQ(texture->unit, 7);
  EXPECT_EQ(texture->kind, LegacyBuiltinKind::Matrix);

  const auto normal = findLegacyBuiltin("gl_NormalMatrix");
  ASSERT_TRUE(normal);
  EXPECT_EQ(normal->kind, LegacyBuiltinKind::DerivedMatrix);
  EXPECT_EQ(normal->type, ValueType::Mat3);

  const auto coords = findLegacyBuiltin("gl_MultiTexCoord2");
  ASSERT_TRUE(coords);
  EXPECT_EQ(coords->kind, LegacyBuiltinKind::Attribute);
  EXPECT_EQ(coords->unit, 2);
  EXPECT_EQ(findLegacyBuiltin("gl_Normal")->type, ValueType::Vec3);
}

TEST(LegacyBuiltins, MisspellingsAndUnitsOutOfRangeAreNotBuiltins) {
  for (const char* name : {"gl_ModelviewMatrix", "gl_TextureMatrix", "gl_TextureMatrix[8]",
                           "gl_TextureMatrix[01]", "gl_TextureMatrix[1", "gl_TextureMatrix1",
                           "gl_MultiTexCoord", "gl_MultiTexCoord9", "gl_Color", "ModelViewMatrix"})
    EXPECT_FALSE(findLegacyBuiltin(name)) << name;
}

Value mat4(const Mat4d& m) { return toMat4Value(m); }

TEST(LegacyBuiltins, DerivedStateFollowsGlsDefinitions) {
  // A scale and a translation: the inverse transpose and the product are
  // exact in fp32, so the expected values are too.
  Mat4d modelview = identity4();
  modelview[0] = 2;
  modelview[5] = 4;
  modelview[10] = 0.5;
  modelview[12] = 3;
  Mat4d projection = identity4();
  projection[0] = 0.25;
  projection[11] = -1;
  projection[15] = 0;
  const UniformMap given = {{"gl_ModelViewMatrix", mat4(modelview)},
                            {"gl_ProjectionMatrix", mat4(projection)}};
  const UniformMap derived = withDerivedLegacyState(given);
  const Value& normal = derived.at("gl_NormalMatrix");
  EXPECT_EQ(normal.type, ValueType::Mat3);
  EXPECT_EQ(normal.data, (std::vector<float>{0.5f, 0, 0, 0, 0.25f, 0, 0, 0, 2}));
  const Value& mvp = derived.at("gl_ModelViewProjectionMatrix");
  EXPECT_EQ(mvp.data, mat4(multiply(projection, modelview)).data);
  EXPECT_EQ(derived.at("gl_ModelViewMatrix").data, given.at("gl_ModelViewMatrix").data);
}

TEST(LegacyBuiltins, DerivedStateReplacesValuesGivenUnderItsNames) {
  const UniformMap given = {{"gl_ModelViewMatrix", mat4(identity4())},
                            {"gl_NormalMatrix", Value{ValueType::Mat3, std::vector<float>(9, 7)}}};
  const UniformMap derived = withDerivedLegacyState(given);
  EXPECT_EQ(derived.at("gl_NormalMatrix").data, (std::vector<float>{1, 0, 0, 0, 1, 0, 0, 0, 1}));
  // No projection, no product.
  EXPECT_FALSE(derived.contains("gl_ModelViewProjectionMatrix"));
}

TEST(LegacyBuiltins, NothingIsDerivedWithoutAModelview) {
  const UniformMap given = {{"gl_ProjectionMatrix", mat4(identity4())}};
  EXPECT_EQ(withDerivedLegacyState(given).size(), 1u);
}

TEST(LegacyBuiltins, ARigidModelviewIsItsOwnNormalMatrix) {
  const Value rigid = mat4(multiply(translation({1, 2, 3}), rotation({1, 2, 0.5}, 0.7)));
  const UniformMap derived = withDerivedLegacyState({{"gl_ModelViewMatrix", rigid}});
  const std::vector<float>& normal = derived.at("gl_NormalMatrix").data;
  for (int column = 0; column < 3; ++column)
    for (int row = 0; row < 3; ++row)
      EXPECT_EQ(normal[static_cast<std::size_t>(column * 3 + row)],
                rigid.data[static_cast<std::size_t>(column * 4 + row)]);
}

// The scenes' own normal matrix (from the double modelview) and the one
// derived from the fp32 modelview that a backend gets agree for every
// scene: a manifest binding either gives a listing the same values.
TEST(LegacyBuiltins, DerivedNormalMatrixMatchesTheScenes) {
  for (const char* name : {"sphere", "sweep", "torus"}) {
    const Scene scene = makeScene(name);
    const UniformMap derived =
        withDerivedLegacyState({{"gl_ModelViewMatrix", scene.values.at("modelview")}});
    EXPECT_EQ(derived.at("gl_NormalMatrix").data, scene.values.at("normal_matrix").data) << name;
  }
}

}  // namespace
}  // namespace snell
