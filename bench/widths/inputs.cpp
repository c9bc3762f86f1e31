#include "widths/inputs.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <random>

#include "core/case.h"
#include "core/manifest.h"
#include "core/scene.h"
#include "widths/listing_runs.h"

namespace snell::widths {
namespace {

using Vec3 = std::array<double, 3>;

Vec3 randomUnit(std::mt19937_64& random) {
  std::normal_distribution<double> normal;
  Vec3 v{normal(random), normal(random), normal(random)};
  const double length = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  for (double& c : v) c /= length;
  return v;
}

// A unit vector perpendicular to n.
Vec3 tangentOf(const Vec3& n, std::mt19937_64& random) {
  const Vec3 r = randomUnit(random);
  const double d = r[0] * n[0] + r[1] * n[1] + r[2] * n[2];
  Vec3 t{r[0] - d * n[0], r[1] - d * n[1], r[2] - d * n[2]};
  const double length = std::sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
  for (double& c : t) c /= length;
  return t;
}

std::vector<float> floats(const Vec3& v) {
  return {static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2])};
}

// I with dot(N, I) = cosine (negative: the ray arrives against N).
BuiltinInput withCosine(double cosine, float eta, std::mt19937_64& random) {
  const Vec3 n = randomUnit(random);
  const Vec3 t = tangentOf(n, random);
  const double sine = std::sqrt(std::max(0.0, 1.0 - cosine * cosine));
  const Vec3 i{cosine * n[0] + sine * t[0], cosine * n[1] + sine * t[1],
               cosine * n[2] + sine * t[2]};
  return {floats(i), floats(n), eta};
}

}  // namespace

std::vector<BuiltinInputSet> builtinInputSets(std::size_t perSet, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<BuiltinInputSet> sets;
  BuiltinInputSet reflectRandom{"reflect", "random", {}};
  BuiltinInputSet reflectGrazing{"reflect", "grazing", {}};
  BuiltinInputSet refractRandom{"refract", "random", {}};
  BuiltinInputSet refractCritical{"refract", "near-critical", {}};
  BuiltinInputSet refractGrazing{"refract", "grazing", {}};
  BuiltinInputSet refractNearOne{"refract", "eta-near-1", {}};
  for (std::size_t s = 0; s < perSet; ++s) {
    reflectRandom.inputs.push_back({floats(randomUnit(random)), floats(randomUnit(random)), 1.0f});
    reflectGrazing.inputs.push_back(
        withCosine(-std::pow(10.0, -1 - 3 * unit(random)), 1.0f, random));
    refractRandom.inputs.push_back(
        withCosine(-unit(random), static_cast<float>(0.5 + 1.5 * unit(random)), random));
    // k = 1 - eta^2 (1 - d^2) within 1e-4 of 0: d^2 = 1 - (1 - k) / eta^2.
    const double eta = 1.0 + 0.6 * unit(random);
    const double k = (unit(random) - 0.5) * 2e-4;
    refractCritical.inputs.push_back(withCosine(
        -std::sqrt(std::max(0.0, 1.0 - (1.0 - k) / (eta * eta))), static_cast<float>(eta), random));
    refractGrazing.inputs.push_back(withCosine(-std::pow(10.0, -1 - 3 * unit(random)),
                                               static_cast<float>(0.5 + unit(random)), random));
    const double nearOne = 1.0 + (unit(random) - 0.5) * 0.06;
    refractNearOne.inputs.push_back(withCosine(-std::pow(10.0, -0.5 - 2.5 * unit(random)),
                                               static_cast<float>(nearOne), random));
  }
  // Issue 9's reproductions (Mesa's grouping with FMA; dEQP's k2 rounded toward zero).
  refractNearOne.inputs.push_back({{0.826009452f, -0.141244575f, -0.545672357f},
                                   {-0.0228234064f, 0.999095142f, -0.0358879417f},
                                   1.00999999f});
  refractNearOne.inputs.push_back({{-0.999026656f, -0.038447462f, -0.0216229353f},
                                   {0.0144414231f, -0.662896097f, 0.748572111f},
                                   0.998186648f});
  for (BuiltinInputSet* set : {&reflectRandom, &reflectGrazing, &refractRandom, &refractCritical,
                               &refractGrazing, &refractNearOne})
    sets.push_back(std::move(*set));
  return sets;
}

namespace {

std::vector<float> randomInput(int components, std::mt19937_64& random) {
  std::uniform_real_distribution<double> symmetric(-1.0, 1.0);
  if (components == 3) return floats(randomUnit(random));
  if (components == 4) {
    std::vector<float> v = floats(randomUnit(random));
    v.push_back(1.0f);
    return v;
  }
  std::vector<float> v;
  for (int k = 0; k < components; ++k) v.push_back(static_cast<float>(symmetric(random)));
  return v;
}

}  // namespace

std::vector<ListingInputSet> listingInputSets(const std::filesystem::path& shaders,
                                              std::size_t vertices, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::vector<ListingInputSet> sets;
  for (const Manifest& m : loadManifests(shaders)) {
    // The widths are the hand-written oracles' (the derived oracle's are
    // the same: tests/oracle/derived).
    if (m.expect == Expectation::CompileError || m.cases.empty() || m.oracle.empty()) continue;
    const ResolvedBindings resolved = resolveBindings(m, makeScene(m.cases.front().scene));
    ListingInputSet set;
    set.oracle = m.oracle;
    set.manifest = m.id;
    set.bindings.uniforms = resolved.uniforms;
    set.bindings.constants = m.constants;
    const std::size_t fromScene = std::min(vertices, resolved.vertexCount);
    const std::size_t stride = fromScene ? resolved.vertexCount / fromScene : 1;
    set.bindings.vertexCount = vertices;
    for (const ListingInput& input : listingInputs(m.oracle)) {
      AttributeStream stream;
      stream.name = input.name;
      stream.components = input.components;
      const auto it = resolved.attributes.find(input.name);
      for (std::size_t v = 0; v < vertices; ++v) {
        if (it != resolved.attributes.end() && v < fromScene) {
          const auto c = static_cast<std::size_t>(input.components);
          const auto begin = it->second.data.begin() + static_cast<std::ptrdiff_t>(v * stride * c);
          stream.data.insert(stream.data.end(), begin, begin + static_cast<std::ptrdiff_t>(c));
        } else {
          const std::vector<float> value = randomInput(input.components, random);
          stream.data.insert(stream.data.end(), value.begin(), value.end());
        }
      }
      set.bindings.attributes.emplace(input.name, std::move(stream));
    }
    sets.push_back(std::move(set));
  }
  return sets;
}

}  // namespace snell::widths
