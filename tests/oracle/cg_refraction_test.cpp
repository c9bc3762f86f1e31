// The Cg Tutorial's C7E3v_refraction through the VertexOracle interface, on
// the suite's own sphere and sweep scenes bound as the manifests bind them:
// T against the tutorial's formula written out in double from the world
// position and normal, the built-in variant against the tutorial's, and the
// intervals against the double and float results and a changed etaRatio.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/errors.h"
#include "core/scene.h"
#include "oracle/vertex_oracle.h"
#include "test_geometry.h"

namespace snell {
namespace {

using test::Dir;

const float kAirToGlass = static_cast<float>(1.0003 / 1.5);  // the manifests' etaRatio
const float kGlassToAir = static_cast<float>(1.5 / 1.0003);

// A scene's values under the listing's GLSL names, as the manifests bind them.
struct Bound {
  Scene scene;
  UniformMap uniforms;
  ConstantMap constants;
  AttributeMap attributes;

  Bound(const std::string& sceneName, float etaRatio) : scene(makeScene(sceneName)) {
    uniforms["etaRatio"] = Value{ValueType::Float, {etaRatio}};
    uniforms["eyePositionW"] = scene.values.at("eye_position");
    uniforms["modelViewProj"] = scene.values.at("modelview_projection");
    uniforms["modelToWorld"] = scene.values.at("model");
    attributes["position"] = scene.attributes.at("position");
    attributes["normal"] = scene.attributes.at("normal");
  }
  OracleInput input() const { return OracleInput{uniforms, constants, attributes, scene.vertexCount}; }
};

const OracleVarying& varying(const std::vector<OracleVarying>& all, const std::string& name) {
  for (const OracleVarying& v : all)
    if (v.name == name) return v;
  throw std::runtime_error("no varying " + name);
}

OracleVarying refracted(const char* oracle, const Bound& bound) {
  return varying(makeVertexOracle(oracle)->evaluate(bound.input()), "T");
}

// The program written out in double: world position and normal, I from the
// eye (not normalized), then the tutorial's refract().
struct Expected {
  Dir T;
  double cosT2;
  double length;  // |I|
};

Expected expectedAt(const Bound& bound, std::size_t vertex, double eta) {
  const std::vector<float>& m = bound.uniforms.at("modelToWorld").data;
  const std::vector<float>& eye = bound.uniforms.at("eyePositionW").data;
  const float* p = &bound.attributes.at("position").data[4 * vertex];
  const float* n = &bound.attributes.at("normal").data[3 * vertex];
  Dir world{}, normal{};
  for (int row = 0; row < 3; ++row) {
    for (int column = 0; column < 3; ++column) {
      world[row] += double(m[column * 4 + row]) * p[column];
      normal[row] += double(m[column * 4 + row]) * n[column];
    }
    world[row] += double(m[12 + row]) * p[3];
  }
  normal = test::unit(normal);
  const Dir I = test::plus(world, Dir{-eye[0], -eye[1], -eye[2]});
  const double c = -test::dotOf(I, normal);
  const double cosT2 = 1.0 - eta * eta * (1.0 - c * c);
  if (cosT2 <= 0.0) return {{0.0, 0.0, 0.0}, cosT2, test::lengthOf(I)};
  return {test::plus(test::scaled(I, eta), test::scaled(normal, eta * c - std::sqrt(cosT2))), cosT2,
          test::lengthOf(I)};
}

TEST(OracleCgRefraction, OutputsTAndGlPosition) {
  for (const char* name : {"cg_refraction", "cg_refraction_builtin"})
    EXPECT_EQ(makeVertexOracle(name)->outputs(), (std::vector<std::string>{"T", "gl_Position"}))
        << name;
}

TEST(OracleCgRefraction, MatchesTheTutorialsFormulaOnBothScenes) {
  for (const char* sceneName : {"sphere", "sweep"}) {
    for (float eta : {kAirToGlass, kGlassToAir}) {
      const Bound bound(sceneName, eta);
      const OracleVarying T = refracted("cg_refraction", bound);
      int zero = 0;
      for (std::size_t v = 0; v < bound.scene.vertexCount; ++v) {
        const Expected e = expectedAt(bound, v, eta);
        if (std::fabs(e.cosT2) < 1e-9) continue;  // double rounding may flip the branch
        zero += e.cosT2 < 0.0;
        for (int k = 0; k < 3; ++k)
          ASSERT_NEAR(T.reference[3 * v + k], e.T[k], 1e-12 * e.length)
              << sceneName << " eta " << eta << " vertex " << v;
        // Near cosT2 = 0 the square root magnifies fp32 rounding without bound.
        if (std::fabs(e.cosT2) < 1e-2) continue;
        for (int k = 0; k < 3; ++k)
          ASSERT_NEAR(T.strict[3 * v + k], e.T[k], 2e-6 * e.length)
              << sceneName << " eta " << eta << " vertex " << v;
      }
      // Air to glass is never totally reflected; glass to air is, wherever
      // (|I| cos(theta))^2 < 1 - 1 / etaRatio^2.
      if (eta == kAirToGlass) {
        EXPECT_EQ(zero, 0) << sceneName;
      } else {
        EXPECT_GT(zero, 100) << sceneName;
      }
    }
  }
}

TEST(OracleCgRefraction, IntervalsHoldTheDoubleAndFloatResultsOnBothScenes) {
  for (const char* oracle : {"cg_refraction", "cg_refraction_builtin"}) {
    for (const char* sceneName : {"sphere", "sweep"}) {
      for (float eta : {kAirToGlass, kGlassToAir}) {
        const OracleVarying T = refracted(oracle, Bound(sceneName, eta));
        int either = 0;
        for (std::size_t k = 0; k < T.reference.size(); ++k) {
          ASSERT_FALSE(T.undefined[k]) << oracle << " " << sceneName << " " << k;
          ASSERT_LE(T.lo[k], T.reference[k]) << oracle << " " << sceneName << " " << k;
          ASSERT_LE(T.reference[k], T.hi[k]) << oracle << " " << sceneName << " " << k;
          ASSERT_LE(T.lo[k], T.strict[k]) << oracle << " " << sceneName << " " << k;
          ASSERT_LE(T.strict[k], T.hi[k]) << oracle << " " << sceneName << " " << k;
          // A union of T and zero where cosT2 may round either way; elsewhere
          // tight: under a ten-thousandth of |I|, which is at most 6 here.
          if (T.lo[k] <= 0.0 && T.hi[k] >= 0.0 && T.hi[k] - T.lo[k] > 1e-3) {
            ++either;
          } else {
            EXPECT_LT(T.hi[k] - T.lo[k], 6e-4) << oracle << " " << sceneName << " " << k;
          }
        }
        // Air to glass never comes near cosT2 = 0. (Glass to air does, but
        // the scenes are not dense there: cg_refract_test.cpp samples it.)
        if (eta == kAirToGlass) {
          EXPECT_EQ(either, 0) << oracle << " " << sceneName;
        }
      }
    }
  }
}

// Algebraically the same formula: cosI is -dot(N, I) exactly and every later
// step rounds symmetrically, so the float results agree bit for bit wherever
// cosT2 is not exactly 0.
TEST(OracleCgRefraction, TheBuiltinVariantAgreesInFloatAwayFromCosT2Zero) {
  for (const char* sceneName : {"sphere", "sweep"}) {
    for (float eta : {kAirToGlass, kGlassToAir}) {
      const Bound bound(sceneName, eta);
      const OracleVarying tutorial = refracted("cg_refraction", bound);
      const OracleVarying builtin = refracted("cg_refraction_builtin", bound);
      for (std::size_t k = 0; k < tutorial.strict.size(); ++k)
        ASSERT_EQ(tutorial.strict[k], builtin.strict[k]) << sceneName << " " << eta << " " << k;
    }
  }
}

// vacuum to glass (1 / 1.5) where the manifests give air to glass
// (1.0003 / 1.5), and 1.5 where they give 1.5 / 1.0003: a vertex's T moves out
// of its interval unless it is zero either way.
TEST(OracleCgRefraction, AChangedEtaRatioMovesTOutOfTheIntervals) {
  const std::pair<float, float> changes[] = {{kAirToGlass, static_cast<float>(1.0 / 1.5)},
                                             {kGlassToAir, 1.5f}};
  for (const char* oracle : {"cg_refraction", "cg_refraction_builtin"}) {
    for (const char* sceneName : {"sphere", "sweep"}) {
      for (const auto& [printed, changed] : changes) {
        const OracleVarying allowed = refracted(oracle, Bound(sceneName, printed));
        const OracleVarying moved = refracted(oracle, Bound(sceneName, changed));
        std::size_t outside = 0, nonZero = 0;
        for (std::size_t v = 0; v < moved.strict.size() / 3; ++v) {
          bool out = false, zero = true;
          for (std::size_t k = 3 * v; k < 3 * v + 3; ++k) {
            out = out || moved.strict[k] < allowed.lo[k] || moved.strict[k] > allowed.hi[k];
            zero = zero && moved.strict[k] == 0.0f && allowed.lo[k] <= 0.0 && allowed.hi[k] >= 0.0;
          }
          outside += out;
          nonZero += !zero;
        }
        EXPECT_GT(nonZero, moved.strict.size() / 12) << oracle << " " << sceneName;
        EXPECT_GE(outside, nonZero * 99 / 100) << oracle << " " << sceneName << " " << changed;
      }
    }
  }
}

TEST(OracleCgRefraction, NamesAMissingEtaRatio) {
  Bound bound("sweep", kAirToGlass);
  bound.uniforms.erase("etaRatio");
  try {
    makeVertexOracle("cg_refraction")->evaluate(bound.input());
    FAIL() << "no UsageError";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("etaRatio"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace snell
