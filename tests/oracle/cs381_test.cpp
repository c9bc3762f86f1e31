// The CS 381 fragments (refraction mapping, chromatic aberration, glass)
// through the VertexOracle interface, fed as the fragment pipeline feeds
// them: one "vertex" per pixel, myvert and mynorm as the driver handed them
// to the fragment. The expected values are the optics written out
// independently: Snell's law for the refracted directions, the mirror law
// for the reflected one.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/errors.h"
#include "oracle/vertex_oracle.h"
#include "test_geometry.h"

namespace snell {
namespace {

using test::Dir;

// `float index = 1.1;` and its neighbours: the float a shader holds.
const double kIndexR = static_cast<float>(1.097);
const double kIndexG = static_cast<float>(1.1);
const double kIndexB = static_cast<float>(1.103);

// Eye-space positions in front of the camera and normals facing it, as
// floats. An interpolated normal is shorter than 1; `normalLength` says by
// how much at most.
struct Pixels {
  std::vector<Dir> positions, normals;
  AttributeMap attributes;
  UniformMap uniforms;
  ConstantMap constants{{"index", 1.1}, {"index_r", 1.097}, {"index_g", 1.1}, {"index_b", 1.103}};

  explicit Pixels(double shortestNormal = 1.0, std::size_t count = 512) {
    std::mt19937_64 rng(381);
    std::uniform_real_distribution<double> distance(1.5, 6.0), shrink(shortestNormal, 1.0),
        cosine(0.0, 1.0);
    AttributeStream myvert{"myvert", 3, {}}, mynorm{"mynorm", 3, {}};
    while (positions.size() < count) {
      Dir view = test::randomUnit(rng);
      if (view[2] > -0.3) continue;  // in front of a camera looking down -z
      // Normal incidence, grazing, and everything between.
      const double c = positions.size() == 0 ? 1.0 : positions.size() == 1 ? 1e-3 : cosine(rng);
      // -dot(view, normal) = c for the unit normal, before any shortening.
      const Dir normal = test::scaled(
          test::plus(test::scaled(view, -c),
                     test::scaled(test::randomTangent(view, rng), std::sqrt(1.0 - c * c))),
          shrink(rng));
      const auto p = test::toFloats(test::scaled(view, distance(rng)));
      const auto n = test::toFloats(normal);
      positions.push_back({p[0], p[1], p[2]});
      normals.push_back({n[0], n[1], n[2]});
      myvert.data.insert(myvert.data.end(), p.begin(), p.end());
      mynorm.data.insert(mynorm.data.end(), n.begin(), n.end());
    }
    attributes["myvert"] = myvert;
    attributes["mynorm"] = mynorm;
  }

  std::vector<OracleVarying> evaluate(const char* oracle) const {
    return makeVertexOracle(oracle)->evaluate(
        OracleInput{uniforms, constants, attributes, positions.size()});
  }
};

// A copy: the tests often look up an output of a temporary result.
OracleVarying varying(const std::vector<OracleVarying>& all, const std::string& name) {
  for (const OracleVarying& v : all)
    if (v.name == name) return v;
  throw std::runtime_error("no varying " + name);
}

Dir at(const std::vector<double>& values, std::size_t pixel) {
  return {values[3 * pixel], values[3 * pixel + 1], values[3 * pixel + 2]};
}

// Snell's law for a unit normal n facing the unit ray v: the refracted ray
// keeps v's tangential part scaled by eta = 1 / index (sin t = eta sin i)
// and goes on into the surface with length 1.
Dir snell(const Dir& v, const Dir& n, double index) {
  const double eta = 1.0 / index;
  const double cosI = -test::dotOf(v, n);
  const Dir tangential = test::plus(v, test::scaled(n, cosI));
  const double sinT2 = eta * eta * (1.0 - cosI * cosI);
  return test::plus(test::scaled(tangential, eta), test::scaled(n, -std::sqrt(1.0 - sinT2)));
}

TEST(OracleCs381, OutputsTheCapturedLocals) {
  EXPECT_EQ(makeVertexOracle("cs381_refraction")->outputs(),
            (std::vector<std::string>{"viewdir", "refractview"}));
  EXPECT_EQ(
      makeVertexOracle("cs381_chromatic_aberration")->outputs(),
      (std::vector<std::string>{"viewdir", "refractview_r", "refractview_g", "refractview_b"}));
  EXPECT_EQ(makeVertexOracle("cs381_glass")->outputs(),
            (std::vector<std::string>{"viewdir", "refractview_r", "refractview_g", "refractview_b",
                                      "reflectview"}));
}

TEST(OracleCs381, RefractionObeysSnellsLaw) {
  const Pixels pixels;
  const auto out = pixels.evaluate("cs381_refraction");
  const OracleVarying& viewdir = varying(out, "viewdir");
  const OracleVarying& refractview = varying(out, "refractview");
  for (std::size_t p = 0; p < pixels.positions.size(); ++p) {
    const Dir v = test::unit(pixels.positions[p]);
    const Dir n = pixels.normals[p];  // unit up to float rounding
    const Dir expected = snell(v, n, kIndexG);
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(viewdir.reference[3 * p + k], v[k], 1e-12) << "pixel " << p;
      EXPECT_NEAR(refractview.reference[3 * p + k], expected[k], 1e-6) << "pixel " << p;
      EXPECT_NEAR(refractview.strict[3 * p + k], expected[k], 1e-5) << "pixel " << p;
    }
    // The law itself, on the oracle's double result: sin t = sin i / index,
    // into the surface, unit length.
    const Dir r = at(refractview.reference, p);
    const double sinI = test::lengthOf(test::crossOf(v, n));
    EXPECT_NEAR(test::lengthOf(test::crossOf(r, n)), sinI / kIndexG, 1e-6) << "pixel " << p;
    EXPECT_LT(test::dotOf(r, n), 0.0) << "pixel " << p;
    EXPECT_NEAR(test::lengthOf(r), 1.0, 1e-6) << "pixel " << p;
  }
}

TEST(OracleCs381, ChromaticAberrationBendsBlueMostAndGreenAsTheRefractionFragment) {
  const Pixels pixels;
  const auto chromatic = pixels.evaluate("cs381_chromatic_aberration");
  const OracleVarying& single = varying(pixels.evaluate("cs381_refraction"), "refractview");
  const OracleVarying& red = varying(chromatic, "refractview_r");
  const OracleVarying& green = varying(chromatic, "refractview_g");
  const OracleVarying& blue = varying(chromatic, "refractview_b");
  // index_g is the refraction fragment's index: the same expression.
  EXPECT_EQ(green.reference, single.reference);
  EXPECT_EQ(green.strict, single.strict);
  EXPECT_EQ(green.lo, single.lo);
  EXPECT_EQ(green.hi, single.hi);
  for (std::size_t p = 2; p < pixels.positions.size(); ++p) {  // not head on, not grazing
    const Dir v = test::unit(pixels.positions[p]);
    const Dir n = pixels.normals[p];
    const Dir expected[] = {snell(v, n, kIndexR), snell(v, n, kIndexG), snell(v, n, kIndexB)};
    const OracleVarying* channels[] = {&red, &green, &blue};
    for (int c = 0; c < 3; ++c)
      for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(channels[c]->reference[3 * p + k], expected[c][k], 1e-6) << "pixel " << p;
    // A higher index bends the ray nearer the inward normal.
    const auto sine = [&](const OracleVarying& r) {
      return test::lengthOf(test::crossOf(at(r.reference, p), n));
    };
    if (test::lengthOf(test::crossOf(v, n)) > 0.05) {
      EXPECT_GT(sine(red), sine(green)) << "pixel " << p;
      EXPECT_GT(sine(green), sine(blue)) << "pixel " << p;
    }
  }
}

TEST(OracleCs381, GlassReflectsByTheMirrorLawAndRefractsAsTheChromaticFragment) {
  const Pixels pixels;
  const auto glass = pixels.evaluate("cs381_glass");
  const auto chromatic = pixels.evaluate("cs381_chromatic_aberration");
  for (const char* name : {"viewdir", "refractview_r", "refractview_g", "refractview_b"}) {
    EXPECT_EQ(varying(glass, name).reference, varying(chromatic, name).reference) << name;
    EXPECT_EQ(varying(glass, name).lo, varying(chromatic, name).lo) << name;
    EXPECT_EQ(varying(glass, name).hi, varying(chromatic, name).hi) << name;
  }
  const OracleVarying& reflectview = varying(glass, "reflectview");
  for (std::size_t p = 0; p < pixels.positions.size(); ++p) {
    const Dir v = test::unit(pixels.positions[p]);
    const Dir n = pixels.normals[p];
    const Dir expected = test::plus(v, test::scaled(n, -2.0 * test::dotOf(n, v)));
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(reflectview.reference[3 * p + k], expected[k], 1e-12) << "pixel " << p;
      EXPECT_NEAR(reflectview.strict[3 * p + k], expected[k], 1e-5) << "pixel " << p;
    }
  }
}

// Interpolated normals (shorter than 1, as the notes pass mynorm straight
// to refract) as well as unit ones; entering a denser medium, so never
// totally reflected and never undefined.
TEST(OracleCs381, IntervalsHoldTheDoubleAndFloatResults) {
  for (double shortest : {1.0, 0.9}) {
    const Pixels pixels(shortest);
    for (const char* oracle : {"cs381_refraction", "cs381_chromatic_aberration", "cs381_glass"}) {
      for (const OracleVarying& out : pixels.evaluate(oracle)) {
        for (std::size_t k = 0; k < out.reference.size(); ++k) {
          ASSERT_FALSE(out.undefined[k]) << oracle << " " << out.name << " " << k;
          ASSERT_LE(out.lo[k], out.reference[k]) << oracle << " " << out.name << " " << k;
          ASSERT_LE(out.reference[k], out.hi[k]) << oracle << " " << out.name << " " << k;
          ASSERT_LE(out.lo[k], out.strict[k]) << oracle << " " << out.name << " " << k;
          ASSERT_LE(out.strict[k], out.hi[k]) << oracle << " " << out.name << " " << k;
          // A bound, not the whole line: unit rays stay well under 1e-5.
          EXPECT_LT(out.hi[k] - out.lo[k], 1e-5) << oracle << " " << out.name << " " << k;
        }
      }
    }
  }
}

// The index comes from the manifest: 1.2 where the notes print 1.1 moves
// every refracted ray that is not head on out of its interval.
TEST(OracleCs381, AChangedIndexMovesTheRefractedRayOutOfItsInterval) {
  const Pixels printed;
  Pixels changed;
  changed.constants["index"] = 1.2;
  const OracleVarying& allowed = varying(printed.evaluate("cs381_refraction"), "refractview");
  const OracleVarying& moved = varying(changed.evaluate("cs381_refraction"), "refractview");
  std::size_t outside = 0;
  for (std::size_t p = 1; p < printed.positions.size(); ++p) {
    bool out = false;
    for (std::size_t k = 3 * p; k < 3 * p + 3; ++k)
      out = out || moved.strict[k] < allowed.lo[k] || moved.strict[k] > allowed.hi[k];
    outside += out;
  }
  EXPECT_EQ(outside, printed.positions.size() - 1);
}

TEST(OracleCs381, NamesAMissingConstant) {
  Pixels pixels;
  pixels.constants.erase("index_b");
  try {
    pixels.evaluate("cs381_glass");
    FAIL() << "no UsageError";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("index_b"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace snell
