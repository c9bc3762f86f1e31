#pragma once
// The catalog listings the derived oracle covers, each with the bindings
// its manifest gives (GLSL name -> scene value), for running the derived
// and the hand-written oracle side by side on a scene.
#include <fstream>
#include <map>
#include <optional>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "../test_geometry.h"
#include "core/manifest.h"
#include "core/scene.h"
#include "core/values.h"
#include "derived/derived_vertex_oracle.h"
#include "derived/evaluate.h"
#include "derived/lower_glsl.h"

namespace snell::test {

inline std::string readListing(const std::string& relative) {
  const std::string path = std::string(SNELL_SOURCE_ROOT) + "/shaders/" + relative;
  std::ifstream file(path);
  if (!file) throw std::runtime_error("cannot read " + path);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

struct DerivedListing {
  const char* oracle;  // the hand-written oracle's registry name
  const char* shader;  // under shaders/
  derived::Stage stage = derived::Stage::Vertex;
  std::map<std::string, std::string> uniforms;  // GLSL name -> scene value
  std::map<std::string, Value> literalUniforms;
  std::map<std::string, std::string> inputs;  // GLSL name -> scene attribute
  ConstantMap constants;                      // the manifest's, for the hand-written oracle
  // A fragment listing's inputs are its vertex stage's outputs: that stage,
  // derived too, gives them (the strict fp32 values, as a driver would).
  const char* vertexStage = nullptr;
  const char* variant = nullptr;  // a second binding of the same listing
  // A fragment listing whose inputs are values it computes itself (the
  // Shadertoy post's uv and point_normal, read back at its probes): its
  // manifest, under shaders/, gives the constants and each capture's line,
  // and the pixels are eye rays hitting the post's sphere.
  const char* manifest = nullptr;

  bool readsBackItsOwnValues() const { return manifest != nullptr; }

  std::string label() const {
    return variant ? std::string(oracle) + "_" + variant : std::string(oracle);
  }
};

inline const std::vector<DerivedListing>& derivedListings() {
  static const std::map<std::string, std::string> kOrangeBookUniforms = {
      {"MVMatrix", "modelview"},
      {"MVPMatrix", "modelview_projection"},
      {"NormalMatrix", "normal_matrix"},
      {"TextureMatrix", "texture_matrix"}};
  static const std::map<std::string, std::string> kCgUniforms = {
      {"eyePositionW", "eye_position"},
      {"modelViewProj", "modelview_projection"},
      {"modelToWorld", "model"}};
  // 1.0003 / 1.5, as the manifests bind it.
  static const std::map<std::string, Value> kCgEta = {
      {"etaRatio", Value{ValueType::Float, {static_cast<float>(0.6668666666666666)}}}};
  // 1.5 / 1.0003 (c7e3v-refraction-glass-to-air).
  static const std::map<std::string, Value> kCgGlassToAirEta = {
      {"etaRatio", Value{ValueType::Float, {static_cast<float>(1.4995501349595122)}}}};
  static const std::map<std::string, std::string> kCs381Vertex = {
      {"modelViewMatrix", "modelview"},
      {"modelViewProjectionMatrix", "modelview_projection"},
      {"normalMatrix", "normal_matrix"}};
  // The blog listings read GL's fixed-function state; the manifests bind
  // gl_TextureMatrix[1] to a quarter turn about z with a translation.
  static const std::map<std::string, std::string> kLegacy = {
      {"gl_ModelViewMatrix", "modelview"},
      {"gl_ProjectionMatrix", "projection"},
      {"gl_TextureMatrix[0]", "texture_matrix"}};
  static const std::map<std::string, Value> kLegacyTextureMatrix1 = {
      {"gl_TextureMatrix[1]", Value{ValueType::Mat4,
                                    {0.0f, 1.0f, 0.0f, 0.0f, -1.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f,
                                     1.0f, 0.0f, 0.25f, -0.125f, 0.5f, 1.0f}}}};
  static const std::vector<DerivedListing> listings = {
      {"orange_book_fresnel",
       "orange-book/14.1-fresnel/fresnel.vert",
       derived::Stage::Vertex,
       kOrangeBookUniforms,
       {},
       {{"MCvertex", "position"}, {"MCnormal", "normal"}},
       {{"Eta", 0.66}, {"FresnelPower", 5.0}}},
      {"orange_book_chromatic",
       "orange-book/14.3-chromatic/chromatic.vert",
       derived::Stage::Vertex,
       kOrangeBookUniforms,
       {},
       {{"MCVertex", "position"}, {"MCNormal", "normal"}},
       {{"EtaR", 0.65}, {"EtaG", 0.67}, {"EtaB", 0.69}, {"FresnelPower", 5.0}}},
      {"orange_book_diffraction",
       "orange-book/14.2-diffraction/diffraction.vert",
       derived::Stage::Vertex,
       {{"MVMatrix", "modelview"},
        {"MVPMatrix", "modelview_projection"},
        {"NormalMatrix", "normal_matrix"}},
       {{"EyePosition", Value{ValueType::Vec3, {0.0f, 0.0f, 0.0f}}},
        {"LightPosition", Value{ValueType::Vec3, {3.0f, -3.0f, 0.0f}}}},
       {{"MCVertex", "position"}, {"MCNormal", "normal"}, {"Tangent", "tangent"}},
       {{"ultraviolet", 400.0}, {"infrared", 700.0}, {"c", 10.0}, {"diffAtten", 0.8}}},
      {"cg_refraction",
       "cg-tutorial/c7e3v-refraction/c7e3v_refraction.vert",
       derived::Stage::Vertex,
       kCgUniforms,
       kCgEta,
       {{"position", "position"}, {"normal", "normal"}},
       {}},
      {"cg_refraction_builtin",
       "cg-tutorial/c7e3v-refraction-builtin/c7e3v_refraction_builtin.vert",
       derived::Stage::Vertex,
       kCgUniforms,
       kCgEta,
       {{"position", "position"}, {"normal", "normal"}},
       {}},
      // The same listing leaving glass for air: total internal reflection
      // past the critical angle, and samples where `cosT2 > 0.0` may go
      // either way.
      {"cg_refraction",
       "cg-tutorial/c7e3v-refraction/c7e3v_refraction.vert",
       derived::Stage::Vertex,
       kCgUniforms,
       kCgGlassToAirEta,
       {{"position", "position"}, {"normal", "normal"}},
       {},
       nullptr,
       "glass_to_air"},
      {"cg_refraction_decal",
       "cg-tutorial/c7e4f-refraction/c7e3v_refraction.vert",
       derived::Stage::Vertex,
       kCgUniforms,
       kCgEta,
       {{"position", "position"}, {"texCoord", "texcoord"}, {"normal", "normal"}},
       {}},
      {"blog_fresnel",
       "blog/fresnel/fresnel.vert",
       derived::Stage::Vertex,
       kLegacy,
       kLegacyTextureMatrix1,
       {{"gl_Vertex", "position"}, {"gl_Normal", "normal"}},
       {{"Eta", 0.6}, {"FresnelPower", 5.0}}},
      {"blog_chromatic",
       "blog/chromatic/chromatic.vert",
       derived::Stage::Vertex,
       kLegacy,
       kLegacyTextureMatrix1,
       {{"gl_Vertex", "position"}, {"gl_Normal", "normal"}},
       {{"Eta", 0.6}, {"EtaR", 0.3}, {"EtaG", 0.67}, {"EtaB", 0.9}, {"FresnelPower", 5.0}}},
      {"blog_diffraction",
       "blog/diffraction/diffraction.vert",
       derived::Stage::Vertex,
       {{"gl_ModelViewMatrix", "modelview"}, {"gl_ProjectionMatrix", "projection"}},
       {{"eyeposition", Value{ValueType::Vec3, {0.0f, 0.0f, 0.0f}}},
        {"lightposition", Value{ValueType::Vec3, {3.0f, -3.0f, 0.0f}}}},
       {{"gl_Vertex", "position"}, {"gl_Normal", "normal"}, {"Tangent", "tangent"}},
       {{"ultraviolet", 400.0}, {"infrared", 700.0}, {"c", 10.0}, {"diffAtten", 0.8}}},
      {"cs381_refraction",
       "cs381/refraction/refraction.frag",
       derived::Stage::Fragment,
       kCs381Vertex,
       {},
       {{"vertex", "position"}, {"normal", "normal"}},
       {{"index", 1.1}},
       "cs381/refraction/eyespace.vert"},
      {"cs381_chromatic_aberration",
       "cs381/chromatic-aberration/chromatic.frag",
       derived::Stage::Fragment,
       kCs381Vertex,
       {},
       {{"vertex", "position"}, {"normal", "normal"}},
       {{"index_r", 1.097}, {"index_g", 1.1}, {"index_b", 1.103}},
       "cs381/chromatic-aberration/eyespace.vert"},
      {"cs381_glass",
       "cs381/glass/glass.frag",
       derived::Stage::Fragment,
       kCs381Vertex,
       {},
       {{"vertex", "position"}, {"normal", "normal"}},
       {{"index_r", 1.097}, {"index_g", 1.1}, {"index_b", 1.103}},
       "cs381/glass/eyespace.vert"},
      {"snell_method_directions",
       "methods/fresnel/1-constant-mix/directions.vert",
       derived::Stage::Vertex,
       kOrangeBookUniforms,
       {},
       {{"MCvertex", "position"}, {"MCnormal", "normal"}},
       {{"Eta", 0.6666667}, {"Mix", 0.1}}},
      {"snell_method_empirical",
       "methods/fresnel/2-empirical/empirical.vert",
       derived::Stage::Vertex,
       kOrangeBookUniforms,
       {},
       {{"MCvertex", "position"}, {"MCnormal", "normal"}},
       {{"Eta", 0.6666667}, {"Bias", 0.0}, {"Scale", 0.25}, {"Power", 1.97}}},
      {"snell_method_per_fragment",
       "methods/fresnel/4-schlick-fragment/per_fragment.vert",
       derived::Stage::Vertex,
       kOrangeBookUniforms,
       {},
       {{"MCvertex", "position"}, {"MCnormal", "normal"}},
       {{"Eta", 0.6666667}, {"FresnelPower", 5.0}}},
      {"shadertoy_lens",
       "shadertoy/lens/lens.frag",
       derived::Stage::Fragment,
       {},
       {},
       {},
       {},
       nullptr,
       nullptr,
       "shadertoy/lens/manifest.toml"},
      {"shadertoy_lens",
       "shadertoy/concave-lens/concave_lens.frag",
       derived::Stage::Fragment,
       {},
       {},
       {},
       {},
       nullptr,
       "concave",
       "shadertoy/concave-lens/manifest.toml"},
      {"shadertoy_lens_fresnel",
       "shadertoy/lens-fresnel/lens_fresnel.frag",
       derived::Stage::Fragment,
       {},
       {},
       {},
       {},
       nullptr,
       nullptr,
       "shadertoy/lens-fresnel/manifest.toml"},
      {"shadertoy_bubble",
       "shadertoy/bubble/bubble.frag",
       derived::Stage::Fragment,
       {},
       {},
       {},
       {},
       nullptr,
       nullptr,
       "shadertoy/bubble/manifest.toml"},
  };
  return listings;
}

// One listing's bindings on a scene, ready for either oracle.
struct BoundListing {
  UniformMap uniforms;
  AttributeMap attributes;
  std::size_t count = 0;
};

// The Shadertoy post's pixels: uv in [-1, 1]^2 whose eye rays (from the
// origin through (uv, 1)) hit the sphere of centre (0, 0, 2) and radius 1,
// and the exact normal there, as fp32 read-backs; pixel 0 looks at the
// centre (normal incidence).
inline AttributeMap shadertoyPixels(std::size_t count) {
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<float> coordinate(-1.0f, 1.0f);
  AttributeStream uv{"uv", 2, {}}, normal{"point_normal", 3, {}};
  const Dir centre{0.0, 0.0, 2.0};
  while (uv.data.size() < 2 * count) {
    const float x = uv.data.empty() ? 0.0f : coordinate(rng);
    const float y = uv.data.empty() ? 0.0f : coordinate(rng);
    const Dir ray = unit({x, y, 1.0});
    const double b = dotOf(ray, centre);
    const double discriminant = b * b - (dotOf(centre, centre) - 1.0);
    if (discriminant < 0.0) continue;
    const Dir n = unit(plus(scaled(ray, b - std::sqrt(discriminant)), scaled(centre, -1.0)));
    uv.data.insert(uv.data.end(), {x, y});
    for (double c : n) normal.data.push_back(static_cast<float>(c));
  }
  return {{"uv", uv}, {"point_normal", normal}};
}

inline Manifest listingManifest(const DerivedListing& listing) {
  return loadManifest(std::string(SNELL_SOURCE_ROOT) + "/shaders/" + listing.manifest);
}

inline BoundListing bindListing(const DerivedListing& listing, const Scene& scene) {
  BoundListing bound;
  if (listing.readsBackItsOwnValues()) {
    bound.count = 1024;
    bound.attributes = shadertoyPixels(bound.count);
    return bound;
  }
  bound.count = scene.vertexCount;
  for (const auto& [name, semantic] : listing.uniforms)
    bound.uniforms[name] = scene.values.at(semantic);
  for (const auto& [name, value] : listing.literalUniforms) bound.uniforms[name] = value;
  for (const auto& [name, semantic] : listing.inputs) {
    AttributeStream stream = scene.attributes.at(semantic);
    stream.name = name;
    bound.attributes[name] = std::move(stream);
  }
  if (!listing.vertexStage) return bound;
  // The fragment's varyings: the vertex stage's fp32 outputs, per vertex.
  const derived::Program vertex = derived::lowerShader(
      {listing.vertexStage, readListing(listing.vertexStage), derived::Stage::Vertex});
  derived::checkBindings(vertex, bound.uniforms, bound.attributes, bound.count);
  const auto values =
      derived::evaluateProgram<float>(vertex, bound.uniforms, bound.attributes, bound.count);
  AttributeMap varyings;
  for (std::size_t k = 0; k < vertex.outputs.size(); ++k) {
    AttributeStream stream;
    stream.name = vertex.outputs[k].name;
    stream.components = static_cast<int>(vertex.outputs[k].components.size());
    stream.data = values[k];
    varyings[stream.name] = std::move(stream);
  }
  bound.attributes = std::move(varyings);
  return bound;
}

}  // namespace snell::test
