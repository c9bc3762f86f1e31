// The Cg Tutorial's C7E3v_refraction with its texture coordinate and
// C7E4f_refraction (cg_refraction_decal): the vertex part passes texCoord
// through exactly and refracts as cg_refraction does; the fragment part, on
// a constant decal and a constant environment, gives the closed form
// decal + (environment - decal) * transmittance; the reference renderer
// names a missing decal or transmittance.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "core/decal.h"
#include "core/errors.h"
#include "core/scene.h"
#include "oracle/reference/fragment_oracle.h"
#include "oracle/reference/reference_image.h"
#include "oracle/vertex_oracle.h"
#include "reference_scenes.h"

namespace snell {
namespace {

constexpr const char* kOracle = "cg_refraction_decal";
const float kAirToGlass = static_cast<float>(1.0003 / 1.5);

// The sphere's values under the listing's GLSL names, as the manifest binds them.
struct Bound {
  Scene scene = makeScene("sphere");
  UniformMap uniforms;
  ConstantMap constants;
  AttributeMap attributes;

  Bound() {
    uniforms["etaRatio"] = Value{ValueType::Float, {kAirToGlass}};
    uniforms["eyePositionW"] = scene.values.at("eye_position");
    uniforms["modelViewProj"] = scene.values.at("modelview_projection");
    uniforms["modelToWorld"] = scene.values.at("model");
    uniforms["transmittance"] = Value{ValueType::Float, {0.6f}};
    attributes["position"] = scene.attributes.at("position");
    attributes["normal"] = scene.attributes.at("normal");
    attributes["texCoord"] = scene.attributes.at("texcoord");
  }
  OracleInput input() const {
    return OracleInput{uniforms, constants, attributes, scene.vertexCount};
  }
};

const OracleVarying& varying(const std::vector<OracleVarying>& all, const std::string& name) {
  for (const OracleVarying& v : all)
    if (v.name == name) return v;
  throw std::runtime_error("no varying " + name);
}

TEST(OracleCgRefractionDecal, TexCoordPassesThroughExactlyAndTIsCgRefractions) {
  const Bound bound;
  const std::vector<OracleVarying> decal = makeVertexOracle(kOracle)->evaluate(bound.input());
  const std::vector<float>& uv = bound.attributes.at("texCoord").data;
  const OracleVarying& out = varying(decal, "oTexCoord");
  ASSERT_EQ(out.reference.size(), uv.size());
  for (std::size_t k = 0; k < uv.size(); ++k) {
    ASSERT_EQ(out.reference[k], uv[k]) << k;
    ASSERT_EQ(out.strict[k], uv[k]) << k;
    ASSERT_EQ(out.lo[k], uv[k]) << k;
    ASSERT_EQ(out.hi[k], uv[k]) << k;
  }
  const OracleVarying plain =
      varying(makeVertexOracle("cg_refraction")->evaluate(bound.input()), "T");
  const OracleVarying& T = varying(decal, "T");
  EXPECT_EQ(T.reference, plain.reference);
  EXPECT_EQ(T.strict, plain.strict);
  EXPECT_EQ(T.lo, plain.lo);
  EXPECT_EQ(T.hi, plain.hi);
}

TEST(OracleCgRefractionDecal, FragmentPartReadsTwoTexturesAndTransmittance) {
  ASSERT_TRUE(hasFragmentOracle(kOracle));
  const auto fragment = makeFragmentOracle(kOracle);
  const std::vector<FragmentInput> inputs = fragment->inputs();
  ASSERT_EQ(inputs.size(), 2u);
  EXPECT_EQ(inputs[0].name, "oTexCoord");
  EXPECT_EQ(inputs[0].components, 2);
  EXPECT_EQ(inputs[1].name, "T");
  EXPECT_EQ(inputs[1].components, 3);
  EXPECT_EQ(fragment->samplers(), std::vector<std::string>{"environmentMap"});
  EXPECT_EQ(fragment->samplers2D(), std::vector<std::string>{"decalMap"});
  const std::vector<FragmentUniform> uniforms = fragment->uniforms();
  ASSERT_EQ(uniforms.size(), 1u);
  EXPECT_EQ(uniforms[0].name, "transmittance");
  EXPECT_EQ(uniforms[0].type, ValueType::Float);
}

Image constantImage(int size, const std::array<float, 4>& colour) {
  Image image(size, size);
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i) std::copy(colour.begin(), colour.end(), image.at(i, j));
  return image;
}

TEST(OracleCgRefractionDecal, FragmentMixesTheDecalTowardTheEnvironmentByTransmittance) {
  const Image decal = constantImage(4, {0.8f, 0.4f, 0.2f, 1.0f});
  const CubeMap environment = test::constantCubeMap({0.1f, 0.3f, 0.9f});
  const auto fragment = makeFragmentOracle(kOracle);
  for (float transmittance : {0.0f, 0.25f, 0.6f, 1.0f}) {
    const FragmentBindings bindings{{{"environmentMap", &environment}},
                                    {{"decalMap", &decal}},
                                    {{"transmittance", Value{ValueType::Float, {transmittance}}}}};
    // Any coordinate and any nonzero direction: both textures are constant.
    const std::vector<double> in = {0.3, 1.7, 0.2, -1, 0.5};
    const FragmentResult out = fragment->shade(in, bindings);
    const double t = transmittance;
    EXPECT_NEAR(out.color[0], 0.8 + (0.1 - 0.8) * t, 1e-7) << t;
    EXPECT_NEAR(out.color[1], 0.4 + (0.3 - 0.4) * t, 1e-7) << t;
    EXPECT_NEAR(out.color[2], 0.2 + (0.9 - 0.2) * t, 1e-7) << t;
    EXPECT_FALSE(out.undefined);
  }
}

TEST(OracleCgRefractionDecal, ReferenceNamesAMissingDecalAndAMissingTransmittance) {
  Bound bound;
  const Image decal = makeDecal();
  const std::vector<std::uint32_t> indices(bound.scene.indices.begin(),
                                           bound.scene.indices.begin() + 3);
  const auto render = [&](const UniformMap& uniforms, const Image* texture) {
    ReferenceInput input{kOracle,
                         uniforms,
                         bound.constants,
                         bound.attributes,
                         bound.scene.vertexCount,
                         indices,
                         {{"environmentMap", bound.scene.environment.get()}},
                         8,
                         8};
    if (texture) input.textures2D["decalMap"] = texture;
    return renderReferenceImage(input);
  };
  EXPECT_NO_THROW(render(bound.uniforms, &decal));
  try {
    render(bound.uniforms, nullptr);
    FAIL() << "a render without the decal was accepted";
  } catch (const UsageError& error) {
    EXPECT_NE(std::string(error.what()).find("decalMap"), std::string::npos) << error.what();
  }
  UniformMap without = bound.uniforms;
  without.erase("transmittance");
  try {
    render(without, &decal);
    FAIL() << "a render without transmittance was accepted";
  } catch (const UsageError& error) {
    EXPECT_NE(std::string(error.what()).find("transmittance"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace snell
