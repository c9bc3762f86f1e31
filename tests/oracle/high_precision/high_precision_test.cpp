// The oracle checked against a 256-bit MPFR evaluation of the same
// listings and built-ins from the same fp32 inputs (random, and the edges
// of tests/oracle/adversary): the oracle's double value agrees to 1e-12
// relative, and the exact value lies inside the oracle's intervals (inside
// one alternative, whole, where a branch may go either way).
//
// Built-ins are compared where I and N are unit vectors, as GLSL asks.
// Relative error is norm-wise, per output vector: max |double - exact| over
// its components divided by max |exact| (a scalar output: plain relative
// error). A component that cancels to nearly 0 is judged against the
// vector it belongs to, as a read-back vector is.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <span>
#include <string>
#include <vector>

#include "adversary/adversary_inputs.h"
#include "catalog_shaders.h"
#include "core/legacy_builtins.h"
#include "high_precision/mpfr_number.h"
#include "oracle/builtin_probe.h"
#include "oracle/glsl/glsl.h"
#include "oracle/listings/interface_visitors.h"
#include "oracle/vertex_oracle.h"

namespace snell::test {
namespace {

constexpr double kTolerance = 1e-12;

struct Worst {
  double relative = 0.0;
  std::string where;
  std::size_t compared = 0;
  std::size_t outside = 0;  // exact values outside every interval
  std::vector<std::string> firstOutside;

  void see(double r, const std::string& what) {
    ++compared;
    if (r > relative) {
      relative = r;
      where = what;
    }
  }
  void notInside(const std::string& what) {
    ++outside;
    if (firstOutside.size() < 8) firstOutside.push_back(what);
  }
};

// Norm-wise relative error of one output vector; nullopt-like -1 where the
// exact value is not finite or zero.
double relativeError(std::span<const double> value, std::span<const double> exact) {
  double scale = 0.0, error = 0.0;
  for (std::size_t k = 0; k < exact.size(); ++k) {
    if (!std::isfinite(exact[k]) || !std::isfinite(value[k])) return -1.0;
    scale = std::max(scale, std::fabs(exact[k]));
    error = std::max(error, std::fabs(value[k] - exact[k]));
  }
  return scale > 0.0 ? error / scale : (error == 0.0 ? 0.0 : -1.0);
}

std::string describe(std::span<const float> inputs) {
  std::string s;
  for (float x : inputs) s += std::to_string(x) + " ";
  return s;
}

template <int Size>
std::vector<double> exactBuiltin(const BuiltinCall& call) {
  glsl::vec<Mp, Size> I, N;
  for (int k = 0; k < Size; ++k) {
    I[k] = Mp(call.I[static_cast<std::size_t>(k)]);
    N[k] = Mp(call.N[static_cast<std::size_t>(k)]);
  }
  const auto r = call.fn == "reflect" ? glsl::reflect(I, N) : glsl::refract(I, N, Mp(call.eta));
  std::vector<double> out;
  for (int k = 0; k < Size; ++k) out.push_back(r[k].toDouble());
  return out;
}

bool insideOneWay(const BuiltinResult& r, const std::vector<double>& exact) {
  return std::any_of(r.ways.begin(), r.ways.end(), [&](const BuiltinWay& w) {
    for (std::size_t k = 0; k < exact.size(); ++k)
      if (!w.undefined[k] && !(w.lo[k] <= exact[k] && exact[k] <= w.hi[k])) return false;
    return true;
  });
}

bool isUnit(const std::vector<float>& v) {
  double sum = 0.0;
  for (float x : v) sum += static_cast<double>(x) * x;
  return std::fabs(std::sqrt(sum) - 1.0) < 1e-6;
}

void checkBuiltin(const BuiltinCall& call, Worst& worst) {
  const std::vector<double> exact = exactBuiltin<3>(call);
  for (PrecisionRules rules : {PrecisionRules::Glsl, PrecisionRules::Vulkan}) {
    const BuiltinResult r = evaluateBuiltin(call, rules);
    if (std::find(r.undefined.begin(), r.undefined.end(), true) != r.undefined.end()) continue;
    const std::string what = call.fn + " of " + describe(call.I) + "/ " + describe(call.N) +
                             "eta " + std::to_string(call.eta) + " (" + precisionRulesName(rules) +
                             ")";
    if (!insideOneWay(r, exact)) worst.notInside(what);
    // GLSL's reflect and refract ask for unit I and N; off them (a huge N,
    // say) the formula itself cancels and no double evaluation agrees.
    if (rules == PrecisionRules::Glsl && isUnit(call.I) && isUnit(call.N)) {
      const double e = relativeError(r.value, exact);
      if (e >= 0.0) worst.see(e, what);
    }
  }
}

TEST(OracleHighPrecision, ReflectAndRefractAgreeWithMpfr) {
  adversary::Rng rng(0x4d50);
  Worst worst;
  for (int trial = 0; trial < 4000; ++trial) {
    for (adversary::Formula f : {adversary::Formula::Reflect, adversary::Formula::Refract}) {
      const std::vector<float> in = adversary::formulaInputs(f, rng);
      const BuiltinCall call{adversary::formulaName(f),
                             {in[0], in[1], in[2]},
                             {in[3], in[4], in[5]},
                             f == adversary::Formula::Refract ? in[6] : 1.0f};
      checkBuiltin(call, worst);
    }
  }
  // Grazing incidence with eta exactly 1 and just off it: k = d^2.
  for (int e = 2; e <= 23; ++e)
    for (float eta : {1.0f, std::nextafter(1.0f, 2.0f), std::nextafter(1.0f, 0.0f)}) {
      const double a = std::asin(1.0) - std::exp2(-e);
      checkBuiltin({"refract",
                    {static_cast<float>(std::sin(a)), static_cast<float>(-std::cos(a)), 0.0f},
                    {0.0f, 1.0f, 0.0f},
                    eta},
                   worst);
    }
  std::printf("reflect/refract: %zu compared, worst relative error %.3g (%s), %zu outside\n",
              worst.compared, worst.relative, worst.where.c_str(), worst.outside);
  for (const std::string& s : worst.firstOutside) ADD_FAILURE() << "exact value outside: " << s;
  EXPECT_LE(worst.relative, kTolerance) << worst.where;
  EXPECT_GT(worst.compared, 2000u);
}

// At grazing incidence with eta 1 (or one float off it) k = d^2 cancels in
// double (1 - (1 - d^2) keeps 1e-16 / d^2 of it); the reference computes k
// in double-double, so even the small component along N agrees component
// by component, not only relative to the vector.
TEST(OracleHighPrecision, RefractAtGrazingWithEtaNearOneAgreesComponentwise) {
  double worst = 0.0;
  int compared = 0;
  adversary::Rng rng(0x67a2);
  for (int plane = 0; plane < 8; ++plane) {
    // A normal in general position and a direction perpendicular to it.
    std::array<double, 3> n{}, t{};
    for (double& x : n) x = rng.uniform(-1, 1);
    const double nn = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (double& x : n) x /= nn;
    const double tt = std::hypot(n[0], n[1]);
    t = {n[1] / tt, -n[0] / tt, 0.0};
    for (int e = 2; e <= 23; ++e)
      for (float eta : {1.0f, std::nextafter(1.0f, 2.0f), std::nextafter(1.0f, 0.0f)}) {
        // 2^-e from grazing: cos(incidence) = 2^-e.
        const double c = std::exp2(-e), s = std::sqrt(1.0 - c * c);
        BuiltinCall call{"refract", {}, {}, eta};
        for (std::size_t k = 0; k < 3; ++k) {
          call.I.push_back(static_cast<float>(-c * n[k] + s * t[k]));
          call.N.push_back(static_cast<float>(n[k]));
        }
        const std::vector<double> exact = exactBuiltin<3>(call);
        const BuiltinResult r = evaluateBuiltin(call);
        for (std::size_t k = 0; k < 3; ++k) {
          const double error = std::fabs(r.value[k] - exact[k]);
          const double relative = exact[k] != 0.0 ? error / std::fabs(exact[k]) : error;
          worst = std::max(worst, relative);
          ++compared;
          EXPECT_LE(relative, kTolerance)
              << "component " << k << " at 2^-" << e << " from grazing, eta " << eta << ": "
              << r.value[k] << " vs " << exact[k];
        }
      }
  }
  std::printf("grazing refract: %d components, worst componentwise relative error %.3g\n", compared,
              worst);
}

// The listing run over Mp at one vertex: every output component, in visit order.
template <template <class> class Shader>
std::vector<double> exactListing(const UniformMap& uniforms, const ConstantMap& constants,
                                 const AttributeMap& attributes, std::size_t vertex) {
  Shader<Mp> shader{};
  listings::BindUniforms<Mp> bindUniforms(uniforms, constants);
  shader.visit(bindUniforms);
  listings::BindVertex<Mp> bindVertex(attributes, vertex);
  shader.visit(bindVertex);
  shader.main();
  listings::CollectOutputs<Mp> outputs;
  shader.visit(outputs);
  std::vector<double> values;
  for (const Mp& x : outputs.values) values.push_back(x.toDouble());
  return values;
}

bool insideVarying(const OracleVarying& v, std::size_t vertex, std::span<const double> exact) {
  const auto sample = std::find_if(v.alternatives.begin(), v.alternatives.end(),
                                   [&](const SampleAlternatives& s) { return s.sample == vertex; });
  if (sample != v.alternatives.end())
    return std::any_of(sample->ways.begin(), sample->ways.end(), [&](const OracleAlternative& w) {
      for (std::size_t k = 0; k < exact.size(); ++k)
        if (!w.undefined[k] && !(w.lo[k] <= exact[k] && exact[k] <= w.hi[k])) return false;
      return true;
    });
  for (std::size_t k = 0; k < exact.size(); ++k) {
    const std::size_t i = vertex * exact.size() + k;
    if (!v.undefined[i] && !(v.lo[i] <= exact[k] && exact[k] <= v.hi[i])) return false;
  }
  return true;
}

TEST(OracleHighPrecision, EveryListingOutputAgreesWithMpfr) {
  adversary::Rng rng(0x4d51);
  Worst worst;
  std::size_t listingsRun = 0;
  forEachCatalogShader([&]<template <class> class Shader>(const char* name, bool legacy) {
    for (const adversary::ListingInputs& all : adversary::catalogListings()) {
      if (all.oracle != name) continue;
      ++listingsRun;
      // Edge directions as unit vectors (the double value is compared),
      // then with denormals and huge scales (only the intervals are).
      for (const bool unit : {true, false}) {
        const adversary::ListingInputs in = adversary::sampleVertices(all, 40, rng, unit);
        const UniformMap uniforms = legacy ? withDerivedLegacyState(in.uniforms) : in.uniforms;
        for (PrecisionRules rules : {PrecisionRules::Glsl, PrecisionRules::Vulkan}) {
          const std::vector<OracleVarying> varyings = makeVertexOracle(name)->evaluate(
              {in.uniforms, in.constants, in.attributes, in.vertexCount, rules});
          for (std::size_t vertex = 0; vertex < in.vertexCount; ++vertex) {
            const std::vector<double> exact =
                exactListing<Shader>(uniforms, in.constants, in.attributes, vertex);
            std::size_t offset = 0;
            for (const OracleVarying& v : varyings) {
              const auto n = static_cast<std::size_t>(v.components);
              const std::span<const double> mine =
                  std::span<const double>(exact).subspan(offset, n);
              offset += n;
              bool undefined = false;
              for (std::size_t k = 0; k < n; ++k)
                undefined = undefined || v.undefined[vertex * n + k];
              if (undefined) continue;
              const std::string what = std::string(name) + " " + v.name + " vertex " +
                                       std::to_string(vertex) + " (" + precisionRulesName(rules) +
                                       ")";
              if (!insideVarying(v, vertex, mine)) worst.notInside(what);
              if (rules != PrecisionRules::Glsl || !unit) continue;
              const double e =
                  relativeError(std::span<const double>(v.reference).subspan(vertex * n, n), mine);
              if (e >= 0.0) worst.see(e, what);
            }
          }
        }
      }
    }
  });
  std::printf(
      "listings: %zu runs, %zu outputs compared, worst relative error %.3g (%s), %zu "
      "outside\n",
      listingsRun, worst.compared, worst.relative, worst.where.c_str(), worst.outside);
  for (const std::string& s : worst.firstOutside) ADD_FAILURE() << "exact value outside: " << s;
  EXPECT_LE(worst.relative, kTolerance) << worst.where;
  EXPECT_GE(listingsRun, vertexOracleNames().size());
}

}  // namespace
}  // namespace snell::test
