#include "adversary/adversary_inputs.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>

#include "catalog_shaders.h"
#include "core/case.h"
#include "core/errors.h"
#include "core/manifest.h"
#include "core/scene.h"
#include "derived/derived_vertex_oracle.h"
#include "derived/lower_glsl.h"
#include "derived/manifest_requests.h"
#include "oracle/listings/interface_visitors.h"

namespace snell::adversary {
namespace {

using Vec3 = std::array<double, 3>;

Vec3 unitVector(Rng& rng) {
  for (;;) {
    const Vec3 v{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
    const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (n > 0.1 && n <= 1.0) return {v[0] / n, v[1] / n, v[2] / n};
  }
}

double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// A unit vector perpendicular to n.
Vec3 tangent(const Vec3& n, Rng& rng) {
  Vec3 t = unitVector(rng);
  const double d = dot(t, n);
  for (int k = 0; k < 3; ++k) t[k] -= d * n[k];
  const double len = std::sqrt(dot(t, t));
  if (len < 1e-3) return tangent(n, rng);
  return {t[0] / len, t[1] / len, t[2] / len};
}

// The incident direction at angle theta from -n.
Vec3 atAngle(const Vec3& n, double theta, Rng& rng) {
  const Vec3 t = tangent(n, rng);
  Vec3 i;
  for (int k = 0; k < 3; ++k) i[k] = -std::cos(theta) * n[k] + std::sin(theta) * t[k];
  return i;
}

// A float of random sign and magnitude 2^e, e uniform in [lo, hi].
float logUniform(Rng& rng, double lo, double hi) {
  const double magnitude = std::exp2(rng.uniform(lo, hi));
  return static_cast<float>(rng.percent(50) ? magnitude : -magnitude);
}

float denormal(Rng& rng) { return logUniform(rng, -149, -126.01); }

double pickEta(Rng& rng) {
  static constexpr double kCatalog[] = {0.66, 1.0 / 0.66, 1.1,  1.0 / 1.1, 1.097, 1.103, 1.02,
                                        0.98, 1.03,       1.06, 1.09,      0.65,  0.67,  0.9};
  switch (rng.below(4)) {
    case 0:
      return kCatalog[rng.below(static_cast<int>(std::size(kCatalog)))];
    case 1:
      return 1.0 + rng.uniform(-0.05, 0.05);
    case 2:
      return rng.percent(50) ? 1.0 : 1.0 + rng.uniform(-1e-6, 1e-6);
    default:
      return rng.uniform(0.3, 3.0);
  }
}

// Denormal components and huge or tiny scales, now and then.
void roughen(std::vector<float>& v, std::size_t from, std::size_t count, Rng& rng) {
  const int kind = rng.below(12);
  if (kind == 0)
    v[from + static_cast<std::size_t>(rng.below(static_cast<int>(count)))] = denormal(rng);
  if (kind == 1) {
    const double scale = std::exp2(rng.uniform(40, 100));
    for (std::size_t k = from; k < from + count; ++k) v[k] = static_cast<float>(v[k] * scale);
  }
  if (kind == 2) {
    const double scale = std::exp2(rng.uniform(-100, -40));
    for (std::size_t k = from; k < from + count; ++k) v[k] = static_cast<float>(v[k] * scale);
  }
  if (kind == 3) v[from + static_cast<std::size_t>(rng.below(static_cast<int>(count)))] = 0.0f;
}

std::vector<float> incidence(Rng& rng, bool withEta, bool unitOnly = false) {
  const Vec3 n = unitVector(rng);
  const double eta = pickEta(rng);
  Vec3 i;
  switch (rng.below(6)) {
    case 0:  // head on
      i = {-n[0], -n[1], -n[2]};
      break;
    case 1:  // grazing
      i = atAngle(n, M_PI / 2 - std::exp2(rng.uniform(-24, -3)) * (rng.percent(50) ? 1 : -1), rng);
      break;
    case 2: {  // near the critical angle (eta > 1), or any angle
      const double e = eta > 1.0 ? eta : 1.0 / eta;
      const double critical = std::asin(1.0 / e);
      i = atAngle(n, critical + std::exp2(rng.uniform(-26, -4)) * (rng.percent(50) ? 1 : -1), rng);
      break;
    }
    default:
      i = unitVector(rng);
  }
  std::vector<float> v;
  for (double x : i) v.push_back(static_cast<float>(x));
  for (double x : n) v.push_back(static_cast<float>(x));
  if (!unitOnly && rng.percent(15)) {  // N not quite unit
    const double s = rng.uniform(0.5, 2.0);
    for (std::size_t k = 3; k < 6; ++k) v[k] = static_cast<float>(v[k] * s);
  }
  if (!unitOnly) {
    roughen(v, 0, 3, rng);
    roughen(v, 3, 3, rng);
  }
  if (withEta) v.push_back(static_cast<float>(eta));
  return v;
}

float anyFloat(Rng& rng) {
  switch (rng.below(6)) {
    case 0:
      return logUniform(rng, -149, 127);
    case 1:
      return denormal(rng);
    case 2:
      return 0.0f;
    default:
      return static_cast<float>(rng.uniform(-4, 4));
  }
}

float positive(Rng& rng) {
  switch (rng.below(8)) {
    case 0:
      return std::fabs(logUniform(rng, -149, 127));
    case 1:
      return std::fabs(denormal(rng));
    case 2:
      return 0.0f;
    case 3:
      return static_cast<float>(std::exp2(rng.uniform(-1.5, 1.5)));
    case 4:
      return static_cast<float>(rng.percent(50) ? 0.5 : rng.percent(50) ? 1.0 : 2.0);
    default:
      return static_cast<float>(rng.uniform(0, 4));
  }
}

}  // namespace

std::uint64_t Rng::next() {
  std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

double Rng::uniform(double lo, double hi) {
  return lo + (hi - lo) * static_cast<double>(next() >> 11) * 0x1p-53;
}

int Rng::below(int n) { return static_cast<int>(next() % static_cast<std::uint64_t>(n)); }

std::vector<float> formulaInputs(Formula f, Rng& rng) {
  switch (f) {
    case Formula::Reflect:
      return incidence(rng, false);
    case Formula::Refract:
      return incidence(rng, true);
    case Formula::FresnelRatio: {
      std::vector<float> v = incidence(rng, false);
      v.push_back(rng.percent(50) ? 5.0f : static_cast<float>(rng.uniform(0.5, 8)));
      return v;
    }
    case Formula::Normalize:
    case Formula::Length: {
      std::vector<float> v = incidence(rng, false);
      v.resize(3);
      if (rng.percent(20)) v = {anyFloat(rng), anyFloat(rng), anyFloat(rng)};
      return v;
    }
    case Formula::Mix: {
      std::vector<float> v = incidence(rng, false);
      const float a =
          rng.percent(30) ? (rng.percent(50) ? 0.0f : 1.0f) : static_cast<float>(rng.uniform(0, 1));
      v.push_back(rng.percent(10) ? anyFloat(rng) : a);
      return v;
    }
    case Formula::Pow: {
      const float y = rng.percent(30)   ? (rng.percent(50) ? 5.0f : 1.97f)
                      : rng.percent(10) ? anyFloat(rng)
                                        : static_cast<float>(rng.uniform(0, 8));
      return {positive(rng), y};
    }
    case Formula::Exp2:
      return {rng.percent(80) ? static_cast<float>(rng.uniform(-155, 130)) : anyFloat(rng)};
    case Formula::Log2:
    case Formula::Sqrt:
    case Formula::InverseSqrt: {
      float x = positive(rng);
      if (rng.percent(5)) x = -x;
      return {x};
    }
    case Formula::Clamp:
      return {anyFloat(rng), static_cast<float>(rng.uniform(-1, 0)),
              static_cast<float>(rng.uniform(0, 1))};
    case Formula::Divide: {
      float b = anyFloat(rng);
      if (rng.percent(10))
        b = static_cast<float>(std::exp2(rng.percent(50) ? -126 : 126) * rng.uniform(0.99, 1.01));
      return {anyFloat(rng), b};
    }
    case Formula::Dot:
    case Formula::MatrixVector: {
      std::vector<float> v;
      for (int k = 0; k < formulaInputs(f); ++k)
        v.push_back(rng.percent(85) ? static_cast<float>(rng.uniform(-2, 2)) : anyFloat(rng));
      return v;
    }
  }
  return {};
}

namespace {

// A listing's per-invocation inputs (vertex attributes, or a fragment
// listing's values read back at its probes) and their component counts.
std::map<std::string, int> interfaceInputs(const std::string& oracle) {
  std::map<std::string, int> inputs;
  test::forEachCatalogShader([&]<template <class> class Shader>(const char* name, bool) {
    if (oracle != name) return;
    Shader<double> shader{};
    listings::DescribeInterface describe;
    shader.visit(describe);
    for (const listings::InterfaceEntry& e : describe.entries())
      if (e.kind == listings::InterfaceEntry::Kind::Input) inputs[e.name] = componentCount(e.type);
  });
  return inputs;
}

// Values for an input the scene does not give (a fragment listing's
// interpolated vectors): directions and points at random, w = 1.
AttributeStream syntheticInput(const std::string& name, int components, std::size_t vertices,
                               Rng& rng) {
  AttributeStream s{name, components, {}};
  for (std::size_t v = 0; v < vertices; ++v) {
    const Vec3 u = unitVector(rng);
    // A normal arrives nearly unit; a position at any distance.
    const bool normal = name.find("norm") != std::string::npos;
    const double scale = normal || rng.percent(50) ? 1.0 : rng.uniform(0.1, 10.0);
    for (int k = 0; k < components; ++k)
      s.data.push_back(k < 3 ? static_cast<float>(u[static_cast<std::size_t>(k)] * scale) : 1.0f);
  }
  return s;
}

}  // namespace

const std::vector<ListingInputs>& catalogListings() {
  static const std::vector<ListingInputs> listings = [] {
    std::vector<ListingInputs> all;
    std::set<std::pair<std::string, ConstantMap>> seen;
    Rng rng(0x1a7e);
    const std::filesystem::path root = std::filesystem::path(SNELL_SOURCE_ROOT) / "shaders";
    for (const Manifest& manifest : loadManifests(root)) {
      if (manifest.oracle.empty() || manifest.cases.empty()) continue;
      if (!seen.insert({manifest.oracle, manifest.constants}).second) continue;
      const Scene scene = makeScene(manifest.cases.front().scene);
      ResolvedBindings bindings = resolveBindings(manifest, scene);
      if (bindings.vertexCount == 0) bindings.vertexCount = 256;
      for (const auto& [name, components] : interfaceInputs(manifest.oracle))
        if (!bindings.attributes.count(name))
          bindings.attributes.emplace(name,
                                      syntheticInput(name, components, bindings.vertexCount, rng));
      all.push_back(ListingInputs{manifest.oracle, bindings.uniforms, manifest.constants,
                                  bindings.attributes, bindings.vertexCount});
    }
    return all;
  }();
  return listings;
}

const std::vector<DerivedListingInputs>& derivedCatalogListings() {
  static const std::vector<DerivedListingInputs> listings = [] {
    std::vector<DerivedListingInputs> all;
    Rng rng(0xde71);
    const std::filesystem::path root = std::filesystem::path(SNELL_SOURCE_ROOT) / "shaders";
    for (const Manifest& manifest : loadManifests(root)) {
      if (manifest.cases.empty() || manifest.expect == Expectation::CompileError) continue;
      for (derived::Stage stage : {derived::Stage::Vertex, derived::Stage::Fragment}) {
        const std::vector<derived::OutputRequest> wanted =
            derived::captureRequests(manifest, stage);
        if (wanted.empty()) continue;
        const derived::ShaderSource source = derived::stageSource(manifest, stage);
        // A listing gated by its hand-written oracle alone may be outside
        // the derived oracle's subset: left out, and said. One the derived
        // oracle gates must lower (the error stops the test).
        std::optional<derived::ApiPrograms> programs;
        try {
          programs = derived::lowerForEachApi(source, wanted);
        } catch (const UsageError& error) {
          if (manifest.derivedOracle) throw;
          std::fprintf(stderr, "adversary: %s left out: %s\n", manifest.id.c_str(), error.what());
          continue;
        }
        const Scene scene = makeScene(manifest.cases.front().scene);
        ResolvedBindings bindings = resolveBindings(manifest, scene);
        if (bindings.vertexCount == 0) bindings.vertexCount = 256;
        // Inputs the scene does not give (a fragment stage's interpolated
        // values, a capture read back where the oracle cannot follow it),
        // of either API's program.
        for (const derived::Program* program :
             {&programs->openGl, programs->vulkan ? &*programs->vulkan : nullptr}) {
          if (!program) continue;
          for (const derived::Binding& input : program->inputs)
            if (!bindings.attributes.count(input.name))
              bindings.attributes.emplace(input.name, syntheticInput(input.name, input.components,
                                                                     bindings.vertexCount, rng));
        }
        // And the hand-written listing's, which the machine runs too.
        if (!manifest.oracle.empty())
          for (const auto& [name, components] : interfaceInputs(manifest.oracle))
            if (!bindings.attributes.count(name))
              bindings.attributes.emplace(
                  name, syntheticInput(name, components, bindings.vertexCount, rng));
        all.push_back(
            DerivedListingInputs{source, wanted,
                                 ListingInputs{manifest.id, bindings.uniforms, manifest.constants,
                                               bindings.attributes, bindings.vertexCount},
                                 manifest.oracle});
      }
    }
    return all;
  }();
  return listings;
}

ListingInputs sampleVertices(const ListingInputs& all, std::size_t count, Rng& rng,
                             bool unitEdges) {
  ListingInputs r{all.oracle, all.uniforms, all.constants, {}, count};
  std::vector<std::size_t> picked;
  for (std::size_t k = 0; k < count; ++k)
    picked.push_back(static_cast<std::size_t>(rng.next() % all.vertexCount));
  for (const auto& [name, stream] : all.attributes) {
    AttributeStream s{stream.name, stream.components, {}};
    const auto n = static_cast<std::size_t>(stream.components);
    for (std::size_t vertex : picked) {
      std::vector<float> values(stream.data.begin() + static_cast<std::ptrdiff_t>(vertex * n),
                                stream.data.begin() + static_cast<std::ptrdiff_t>(vertex * n + n));
      if (rng.percent(20)) {
        // A direction of an edge case in place of the scene's value.
        const std::vector<float> edge = incidence(rng, false, unitEdges);
        for (std::size_t k = 0; k < std::min<std::size_t>(n, 3); ++k) values[k] = edge[3 + k];
        if (!unitEdges) roughen(values, 0, n, rng);
      }
      s.data.insert(s.data.end(), values.begin(), values.end());
    }
    r.attributes.emplace(name, std::move(s));
  }
  return r;
}

}  // namespace snell::adversary
