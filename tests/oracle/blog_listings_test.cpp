// The blog's legacy listings through the VertexOracle interface, held
// against the listings they share their statements with: the Orange Book's
// Fresnel and diffraction shaders given the same values under their own
// names (GL's derived state computed as core/legacy_builtins.h does), and
// the blog's Fresnel shader for each of the chromatic shader's indices.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "core/errors.h"
#include "core/legacy_builtins.h"
#include "core/scene.h"
#include "oracle/vertex_oracle.h"

namespace snell {
namespace {

const Scene& sphere() {
  static const Scene scene = makeScene("sphere");
  return scene;
}

AttributeStream renamed(const AttributeStream& stream, const std::string& name) {
  AttributeStream out = stream;
  out.name = name;
  return out;
}

// The bindings of a blog manifest: fixed-function state by its gl_ names.
struct Legacy {
  UniformMap uniforms;
  AttributeMap attributes;
};

Legacy legacyBindings() {
  const Scene& scene = sphere();
  Legacy legacy;
  legacy.uniforms["gl_ModelViewMatrix"] = scene.values.at("modelview");
  legacy.uniforms["gl_ProjectionMatrix"] = scene.values.at("projection");
  legacy.uniforms["gl_TextureMatrix[0]"] = scene.values.at("texture_matrix");
  legacy.uniforms["gl_TextureMatrix[1]"] = scene.values.at("texture_matrix");
  legacy.attributes["gl_Vertex"] = renamed(scene.attributes.at("position"), "gl_Vertex");
  legacy.attributes["gl_Normal"] = renamed(scene.attributes.at("normal"), "gl_Normal");
  legacy.attributes["Tangent"] = renamed(scene.attributes.at("tangent"), "Tangent");
  return legacy;
}

std::vector<OracleVarying> run(const std::string& oracle, const UniformMap& uniforms,
                               const ConstantMap& constants, const AttributeMap& attributes) {
  return makeVertexOracle(oracle)->evaluate(
      {uniforms, constants, attributes, sphere().vertexCount});
}

const OracleVarying& named(const std::vector<OracleVarying>& varyings, const std::string& name) {
  for (const OracleVarying& v : varyings)
    if (v.name == name) return v;
  throw std::runtime_error("no output " + name);
}

void expectSame(const OracleVarying& a, const OracleVarying& b, const std::string& what) {
  EXPECT_EQ(a.reference, b.reference) << what;
  EXPECT_EQ(a.strict, b.strict) << what;
  EXPECT_EQ(a.lo, b.lo) << what;
  EXPECT_EQ(a.hi, b.hi) << what;
}

TEST(BlogListings, RegisteredUnderTheirManifestNames) {
  const std::vector<std::string> names = vertexOracleNames();
  for (const char* name : {"blog_fresnel", "blog_chromatic", "blog_diffraction"})
    EXPECT_NE(std::find(names.begin(), names.end(), name), names.end()) << name;
}

TEST(BlogListings, FresnelReflectAndRefractAreTheOrangeBooks) {
  const Legacy legacy = legacyBindings();
  const ConstantMap constants = {{"Eta", 0.6}, {"FresnelPower", 5.0}};
  const std::vector<OracleVarying> blog =
      run("blog_fresnel", legacy.uniforms, constants, legacy.attributes);

  const UniformMap derived = withDerivedLegacyState(legacy.uniforms);
  const UniformMap book = {{"MVMatrix", derived.at("gl_ModelViewMatrix")},
                           {"MVPMatrix", derived.at("gl_ModelViewProjectionMatrix")},
                           {"NormalMatrix", derived.at("gl_NormalMatrix")},
                           {"TextureMatrix", derived.at("gl_TextureMatrix[0]")}};
  const AttributeMap attributes = {
      {"MCvertex", renamed(legacy.attributes.at("gl_Vertex"), "MCvertex")},
      {"MCnormal", renamed(legacy.attributes.at("gl_Normal"), "MCnormal")}};
  const std::vector<OracleVarying> orange = run("orange_book_fresnel", book, constants, attributes);

  expectSame(named(blog, "Reflect"), named(orange, "Reflect"), "Reflect");
  expectSame(named(blog, "Refract"), named(orange, "Refract"), "Refract");
  expectSame(named(blog, "gl_Position"), named(orange, "gl_Position"), "gl_Position");
  // The blog writes 1.0 - dot(i, n) where the book has dot(-i, n): on front
  // faces its Ratio exceeds 1.
  const std::vector<double>& ratio = named(blog, "Ratio").reference;
  EXPECT_GT(*std::max_element(ratio.begin(), ratio.end()), 1.0);
}

TEST(BlogListings, ChromaticIsTheFresnelListingOncePerIndex) {
  const Legacy legacy = legacyBindings();
  const std::vector<OracleVarying> chromatic =
      run("blog_chromatic", legacy.uniforms,
          {{"Eta", 0.6}, {"EtaR", 0.3}, {"EtaG", 0.67}, {"EtaB", 0.9}, {"FresnelPower", 5.0}},
          legacy.attributes);
  auto fresnel = [&](double eta) {
    return run("blog_fresnel", legacy.uniforms, {{"Eta", eta}, {"FresnelPower", 5.0}},
               legacy.attributes);
  };
  const std::vector<OracleVarying> at06 = fresnel(0.6);
  expectSame(named(chromatic, "Ratio"), named(at06, "Ratio"), "Ratio (F from Eta)");
  expectSame(named(chromatic, "Reflect"), named(at06, "Reflect"), "Reflect");
  expectSame(named(chromatic, "RefractR"), named(fresnel(0.3), "Refract"), "RefractR");
  expectSame(named(chromatic, "RefractG"), named(fresnel(0.67), "Refract"), "RefractG");
  expectSame(named(chromatic, "RefractB"), named(fresnel(0.9), "Refract"), "RefractB");
}

TEST(BlogListings, DiffractionIsTheOrangeBooksRewrite) {
  const Legacy legacy = legacyBindings();
  const ConstantMap constants = {
      {"ultraviolet", 400.0}, {"infrared", 700.0}, {"c", 10.0}, {"diffAtten", 0.8}};
  const Value eye{ValueType::Vec3, {0, 0, 0}};
  const Value light{ValueType::Vec3, {3, -3, 0}};
  UniformMap blogUniforms = legacy.uniforms;
  blogUniforms["eyeposition"] = eye;
  blogUniforms["lightposition"] = light;
  const std::vector<OracleVarying> blog =
      run("blog_diffraction", blogUniforms, constants, legacy.attributes);

  const UniformMap derived = withDerivedLegacyState(legacy.uniforms);
  const UniformMap book = {{"MVMatrix", derived.at("gl_ModelViewMatrix")},
                           {"MVPMatrix", derived.at("gl_ModelViewProjectionMatrix")},
                           {"NormalMatrix", derived.at("gl_NormalMatrix")},
                           {"EyePosition", eye},
                           {"LightPosition", light}};
  const AttributeMap attributes = {
      {"MCVertex", renamed(legacy.attributes.at("gl_Vertex"), "MCVertex")},
      {"MCNormal", renamed(legacy.attributes.at("gl_Normal"), "MCNormal")},
      {"Tangent", legacy.attributes.at("Tangent")}};
  const std::vector<OracleVarying> orange =
      run("orange_book_diffraction", book, constants, attributes);
  expectSame(named(blog, "Color"), named(orange, "Color"), "Color");
}

TEST(BlogListings, FtransformNeedsTheProjectionMatrix) {
  Legacy legacy = legacyBindings();
  legacy.uniforms.erase("gl_ProjectionMatrix");
  try {
    run("blog_fresnel", legacy.uniforms, {{"Eta", 0.6}, {"FresnelPower", 5.0}}, legacy.attributes);
    FAIL() << "expected a UsageError";
  } catch (const UsageError& error) {
    EXPECT_NE(std::string(error.what()).find("gl_ModelViewProjectionMatrix"), std::string::npos)
        << error.what();
  }
}

}  // namespace
}  // namespace snell
