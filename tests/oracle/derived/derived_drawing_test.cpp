// The derived oracle's reference-image side (derived/derived_drawing.h)
// and what the gates keep from it: texture lookups and inverse() are
// followed in double for the picture and refused in a gated value; a
// fragment capture is the value after its own line.
#include "derived/derived_drawing.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>

#include "core/environment.h"
#include "core/errors.h"
#include "derived_listings.h"
#include "oracle/glsl/glsl.h"
#include "oracle/glsl/texture.h"

namespace snell::test {
namespace {

bool mentions(const std::string& message, const std::string& part) {
  return message.find(part) != std::string::npos;
}

std::string refusalOf(const derived::ShaderSource& source,
                      const std::vector<derived::OutputRequest>& outputs) {
  try {
    derived::lowerOutputs(source, outputs);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "";
}

constexpr const char* kNormalMatrixVertex = R"(#version 330 core
layout (location = 0) in vec3 aPos;
layout (location = 1) in vec3 aNormal;
out vec3 Normal;
uniform mat4 model;
void main() {
  Normal = mat3(transpose(inverse(model))) * aNormal;
  gl_Position = model * vec4(aPos, 1.0);
}
)";

Value mat4Value(const std::array<float, 16>& columnMajor) {
  return Value{ValueType::Mat4, {columnMajor.begin(), columnMajor.end()}};
}

TEST(DerivedDrawing, InverseIsFollowedForThePictureAndRefusedInAGatedValue) {
  const derived::ShaderSource source{"user.vert", kNormalMatrixVertex, derived::Stage::Vertex};
  const std::string message = refusalOf(source, {{"Normal", 0}});
  EXPECT_TRUE(mentions(message, "user.vert:7: inverse()")) << message;
  EXPECT_TRUE(mentions(message, "4.7.1")) << message;
  // gl_Position does not depend on it: gated as usual.
  EXPECT_EQ(refusalOf(source, {{"gl_Position", 0}}), "");

  // Scale x by 2, z by 4, then translate: the inverse transpose scales the
  // normal by 1/2 and 1/4 (the translation is not in the upper 3 x 3).
  const UniformMap uniforms = {
      {"model", mat4Value({2, 0, 0, 0, 0, 1, 0, 0, 0, 0, 4, 0, 5, 6, 7, 1})}};
  const AttributeMap inputs = {{"aPos", {"aPos", 3, {1, 1, 1}}},
                               {"aNormal", {"aNormal", 3, {1, 1, 1}}}};
  const std::unique_ptr<VertexOracle> oracle = derived::makeDerivedDrawingVertexOracle(source);
  const std::vector<OracleVarying> varyings = oracle->evaluate({uniforms, {}, inputs, 1});
  const OracleVarying& normal = varyings.at(0).name == "Normal" ? varyings[0] : varyings[1];
  ASSERT_EQ(normal.name, "Normal");
  EXPECT_DOUBLE_EQ(normal.reference[0], 0.5);
  EXPECT_DOUBLE_EQ(normal.reference[1], 1.0);
  EXPECT_DOUBLE_EQ(normal.reference[2], 0.25);
}

TEST(DerivedDrawing, ASingularMatrixHasNoInverseAndItsValuesAreUndefined) {
  const derived::ShaderSource source{"user.vert", kNormalMatrixVertex, derived::Stage::Vertex};
  const UniformMap uniforms = {
      {"model", mat4Value({1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1})}};
  const AttributeMap inputs = {{"aPos", {"aPos", 3, {1, 1, 1}}},
                               {"aNormal", {"aNormal", 3, {1, 1, 1}}}};
  const auto varyings =
      derived::makeDerivedDrawingVertexOracle(source)->evaluate({uniforms, {}, inputs, 1});
  bool seen = false;
  for (const OracleVarying& v : varyings) {
    if (v.name != "Normal") continue;
    seen = true;
    for (std::uint8_t undefined : v.undefined) EXPECT_EQ(undefined, 1);
  }
  EXPECT_TRUE(seen);
}

constexpr const char* kRefractionFragment = R"(#version 330 core
out vec4 FragColor;
in vec3 Normal;
in vec3 Position;
uniform vec3 cameraPos;
uniform samplerCube skybox;
void main() {
    float ratio = 1.00 / 1.52;
    vec3 I = normalize(Position - cameraPos);
    vec3 R = refract(I, normalize(Normal), ratio);
    FragColor = vec4(texture(skybox, R).rgb, 1.0);
}
)";

TEST(DerivedDrawing, AFragmentColourSamplesTheCubeMapAsTheHandWrittenTextureDoes) {
  const derived::ShaderSource source{"user.frag", kRefractionFragment, derived::Stage::Fragment};
  const std::unique_ptr<FragmentOracle> fragment = derived::makeDerivedFragmentOracle(source);
  EXPECT_EQ(fragment->samplers(), std::vector<std::string>{"skybox"});
  ASSERT_EQ(fragment->inputs().size(), 2u);
  ASSERT_EQ(fragment->uniforms().size(), 1u);
  EXPECT_EQ(fragment->uniforms()[0].type, ValueType::Vec3);

  const CubeMap environment = makeEnvironment(16);
  FragmentBindings bindings{
      {{"skybox", &environment}}, {}, {{"cameraPos", Value{ValueType::Vec3, {0, 0, 3}}}}};
  std::vector<double> packed;
  for (const FragmentInput& in : fragment->inputs()) {
    if (in.name == "Normal") packed.insert(packed.end(), {0.3, 0.2, 0.9});
    if (in.name == "Position") packed.insert(packed.end(), {0.3, 0.2, 0.9});
  }
  const FragmentResult result = fragment->shade(packed, bindings);

  // The same steps by hand, in double, through the hand-written texture().
  const double x = 0.3f, y = 0.2f, z = 0.9f;  // as the one-sample fp32 streams hold them
  const glsl::vec3<double> p{x, y, z}, n{x, y, z}, eye{0.0, 0.0, 3.0};
  const glsl::vec3<double> I = glsl::normalize(p - eye);
  // `1.00 / 1.52` as written: a division of the two literals, each the
  // nearest float (derived/literal_names.h), as a hand-written oracle has it.
  const glsl::vec3<double> R =
      glsl::refract(I, glsl::normalize(n), glsl::lit<double>(1.00) / glsl::lit<double>(1.52));
  glsl::samplerCube sampler{&environment};
  const glsl::vec4<double> expected = glsl::texture(sampler, R);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(result.color[c], expected[c], 1e-12) << c;
  EXPECT_EQ(result.color[3], 1.0);
  EXPECT_FALSE(result.undefined);

  // Total internal reflection cannot happen entering glass; from inside it
  // can: refract() gives 0, whose lookup the spec leaves undefined.
  const derived::ShaderSource leaving{
      "user.frag",
      std::string(kRefractionFragment)
          .replace(std::string(kRefractionFragment).find("1.00 / 1.52"), 11, "1.52 / 1.00"),
      derived::Stage::Fragment};
  std::vector<double> grazing;
  for (const FragmentInput& in : fragment->inputs()) {
    if (in.name == "Normal") grazing.insert(grazing.end(), {1.0, 0.0, 0.0});
    if (in.name == "Position") grazing.insert(grazing.end(), {0.0, 0.0, 2.0});
  }
  EXPECT_TRUE(derived::makeDerivedFragmentOracle(leaving)->shade(grazing, bindings).undefined);
}

TEST(DerivedDrawing, ALookupInAGatedValueIsRefusedWithItsLine) {
  const derived::ShaderSource source{"user.frag", kRefractionFragment, derived::Stage::Fragment};
  const std::string message = refusalOf(source, {{"FragColor", 0}});
  EXPECT_TRUE(mentions(message, "user.frag:11: a texture lookup")) << message;
  // What the lookup reads is gated as usual.
  EXPECT_EQ(refusalOf(source, {{"R", 10}}), "");
}

TEST(DerivedDrawing, AFragmentCaptureIsTheValueAfterItsOwnLine) {
  const derived::ShaderSource source{"user.frag", R"(#version 330 core
in vec3 a;
out vec4 colour;
void main() {
  vec3 v = a * 2.0;
  v = v + 1.0;
  colour = vec4(v, 1.0);
}
)",
                                     derived::Stage::Fragment};
  const std::unique_ptr<VertexOracle> oracle =
      derived::makeDerivedVectorOracle(source, {{"v", 5}, {"colour", 0}});
  EXPECT_EQ(oracle->inputs(), std::vector<std::string>{"a"});
  const AttributeMap inputs = {{"a", {"a", 3, {1, 2, 3}}}};
  const std::vector<OracleVarying> varyings = oracle->evaluate({{}, {}, inputs, 1});
  ASSERT_EQ(varyings.size(), 2u);
  EXPECT_EQ(varyings[0].reference, (std::vector<double>{2, 4, 6}));     // after line 5
  EXPECT_EQ(varyings[1].reference, (std::vector<double>{3, 5, 7, 1}));  // at the end
  const auto lastLine =
      derived::makeDerivedVectorOracle(source, {{"v", 6}})->evaluate({{}, {}, inputs, 1});
  EXPECT_EQ(lastLine[0].reference, (std::vector<double>{3, 5, 7}));
}

}  // namespace
}  // namespace snell::test
