// The Cg Tutorial's refract() (section 7.3.2) as the oracle writes it,
// against the optics it stands for and against GLSL's built-in: Snell's law
// for a unit I, zero exactly where cosT2 <= 0 (cosT2 == 0 included, where
// GLSL's refract() returns the grazing ray), and intervals that hold the
// double, strict float and fused float evaluations, with I of any length.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "oracle/listings/cg_refract.h"
#include "test_geometry.h"

namespace snell {
namespace {

using listings::cgRefract;
using test::Dir;
using Floats = std::array<float, 3>;

constexpr double kPi = 3.14159265358979323846;

// etaRatio for each pair of media in the tutorial's Table 7-2 (air 1.0003,
// water 1.3333, glass 1.5, diamond 2.417), both ways.
const std::vector<double> kTableRatios = {1.0003 / 1.3333, 1.0003 / 1.5,    1.0003 / 2.417,
                                          1.3333 / 1.0003, 1.5 / 1.0003,    2.417 / 1.0003,
                                          1.3333 / 1.5,    1.5 / 1.3333};

glsl::vec3<double> asVec(const Dir& d) { return glsl::vec3<double>(d[0], d[1], d[2]); }

TEST(OracleCgRefract, ObeysSnellsLawForAUnitIncidentRay) {
  std::mt19937_64 rng(11);
  int refracted = 0, reflected = 0;
  for (double eta : kTableRatios) {
    for (int step = 0; step <= 900; ++step) {
      const double theta = step * (kPi / 2) / 900;
      const Dir normal = test::randomUnit(rng);
      const Dir tangent = test::randomTangent(normal, rng);
      const Dir incident = test::incidentAt(normal, tangent, theta);
      const Dir T = test::fromVec(cgRefract(asVec(incident), asVec(normal), eta));
      const double sinT = eta * std::sin(theta);
      if (std::fabs(sinT - 1.0) < 1e-9) continue;  // the critical angle: see below
      if (sinT > 1.0) {
        EXPECT_EQ(T, (Dir{0.0, 0.0, 0.0})) << "eta " << eta << " theta " << theta;
        ++reflected;
        continue;
      }
      // Snell: the transmitted ray keeps unit length, leans by asin(eta sin(theta)).
      const double along = -test::dotOf(T, normal);
      EXPECT_NEAR(test::lengthOf(T), 1.0, 1e-12);
      EXPECT_NEAR(along, std::sqrt(1.0 - sinT * sinT), 1e-12) << "eta " << eta;
      EXPECT_NEAR(test::dotOf(T, tangent), sinT, 1e-12) << "eta " << eta << " theta " << theta;
      EXPECT_NEAR(test::dotOf(T, test::crossOf(normal, tangent)), 0.0, 1e-12);
      ++refracted;
    }
  }
  EXPECT_GT(refracted, 3000);
  EXPECT_GT(reflected, 1000);  // the dense-to-rare ratios pass their critical angles
}

// The closed form with I of any length: the formula as the tutorial prints
// it, in terms of c = -I.N, with no claim to be physics.
TEST(OracleCgRefract, FollowsItsFormulaForAnUnnormalizedIncidentRay) {
  std::mt19937_64 rng(12);
  for (double eta : kTableRatios) {
    for (double length : {0.25, 2.0, 5.75}) {
      for (int step = 0; step <= 300; ++step) {
        const double theta = step * (kPi / 2) / 300;
        const Dir normal = test::randomUnit(rng);
        const Dir I = test::scaled(test::incidentAt(normal, test::randomTangent(normal, rng), theta),
                                   length);
        const double c = -test::dotOf(I, normal);
        const double cosT2 = 1.0 - eta * eta * (1.0 - c * c);
        const Dir T = test::fromVec(cgRefract(asVec(I), asVec(normal), eta));
        if (cosT2 <= 0.0) {
          EXPECT_EQ(T, (Dir{0.0, 0.0, 0.0}));
          continue;
        }
        const Dir expected = test::plus(test::scaled(I, eta),
                                        test::scaled(normal, eta * c - std::sqrt(cosT2)));
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(T[k], expected[k], 1e-12 * (1 + length));
      }
    }
  }
}

// cosT2 is 0 exactly: eta 1 at grazing incidence. The tutorial returns zero
// ("cosT2 is less than or equal to zero"); GLSL's k < 0.0 test lets k == 0
// through and returns eta * I, the grazing ray.
TEST(OracleCgRefract, ReturnsZeroWhereCosT2IsExactlyZeroAndGlslDoesNot) {
  const Floats I = {1.0f, 0.0f, 0.0f}, N = {0.0f, 1.0f, 0.0f};
  const auto tutorialDouble = cgRefract(test::asVec<double>(I), test::asVec<double>(N), 1.0);
  const auto tutorialFloat = cgRefract(test::asVec<float>(I), test::asVec<float>(N), 1.0f);
  const auto glslDouble = glsl::refract(test::asVec<double>(I), test::asVec<double>(N), 1.0);
  const auto glslFloat = glsl::refract(test::asVec<float>(I), test::asVec<float>(N), 1.0f);
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(tutorialDouble[k], 0.0) << k;
    EXPECT_EQ(tutorialFloat[k], 0.0f) << k;
    EXPECT_EQ(glslDouble[k], I[k]) << k;
    EXPECT_EQ(glslFloat[k], I[k]) << k;
  }
  // Both are allowed: cosT2 may round to either side of 0 on a machine.
  const auto allowed = cgRefract(test::asVec<Interval>(I), test::asVec<Interval>(N),
                                 Interval::point(1.0f));
  for (int k = 0; k < 3; ++k) {
    EXPECT_TRUE(contains(allowed[k], 0.0f)) << k;
    EXPECT_TRUE(contains(allowed[k], I[k])) << k;
  }
}

// The same at the critical angle of a dense-to-rare pair from Table 7-2: a
// unit incident ray whose fp32 cosT2 rounds to 0 exactly. The tutorial's
// float result is zero, GLSL's the unit ray along the surface.
TEST(OracleCgRefract, AtTheCriticalAngleGlslGivesTheGrazingRayWhereTheTutorialGivesZero) {
  const Floats N = {0.0f, 1.0f, 0.0f};
  int found = 0;
  for (double ratio : kTableRatios) {
    if (ratio < 1.0) continue;
    const float eta = static_cast<float>(ratio);
    // The float cosines around the critical one; cosT2 depends on nothing else.
    float c = static_cast<float>(std::sqrt(1.0 - 1.0 / (double(eta) * eta)));
    for (int k = 0; k < 8; ++k) c = std::nextafter(c, 0.0f);
    for (int k = 0; k < 16; ++k, c = std::nextafter(c, 1.0f)) {
      if (1.0f - eta * eta * (1.0f - c * c) != 0.0f) continue;
      const Floats I = {std::sqrt(1.0f - c * c), -c, 0.0f};
      const auto tutorial = cgRefract(test::asVec<float>(I), test::asVec<float>(N), eta);
      const auto glsl = glsl::refract(test::asVec<float>(I), test::asVec<float>(N), eta);
      for (int j = 0; j < 3; ++j) EXPECT_EQ(tutorial[j], 0.0f) << "eta " << eta;
      EXPECT_NEAR(glsl[0], 1.0f, 1e-3f) << "eta " << eta;  // along the surface
      EXPECT_NEAR(glsl[1], 0.0f, 1e-3f) << "eta " << eta;
      EXPECT_EQ(glsl[2], 0.0f) << "eta " << eta;
      const auto allowed =
          cgRefract(test::asVec<Interval>(I), test::asVec<Interval>(N), Interval::point(eta));
      for (int j = 0; j < 3; ++j) {
        EXPECT_TRUE(contains(allowed[j], tutorial[j])) << "eta " << eta;
        EXPECT_TRUE(contains(allowed[j], glsl[j])) << "eta " << eta;
      }
      ++found;
    }
  }
  EXPECT_GT(found, 0) << "no float cosine near a critical angle makes cosT2 exactly 0";
}

// The tutorial's refract() as a fusing compiler may emit it: dot summed from
// the last term with fma, the later steps fused.
glsl::vec3<float> cgRefractFused(const Floats& I, const Floats& N, float eta) {
  const float cosI = std::fma(-I[0], N[0], std::fma(-I[1], N[1], -I[2] * N[2]));
  const float cosT2 = std::fma(-eta * eta, std::fma(-cosI, cosI, 1.0f), 1.0f);
  const float b = std::fma(eta, cosI, -std::sqrt(std::fabs(cosT2)));
  glsl::vec3<float> T;
  if (!(cosT2 > 0.0f)) return T;
  for (int j = 0; j < 3; ++j) T[j] = std::fma(eta, I[j], b * N[j]);
  return T;
}

TEST(OracleCgRefract, IntervalsHoldDoubleStrictAndFusedResultsOnASweep) {
  std::mt19937_64 rng(13);
  int checked = 0, eitherWay = 0, zero = 0;
  for (double ratio : kTableRatios) {
    const float eta = static_cast<float>(ratio);
    for (double length : {1.0, 2.5, 5.75}) {
      // Evenly to just past grazing, then densely around cosT2 = 0, where
      // |I| cos(theta) = sqrt(1 - 1 / eta^2) when eta > 1.
      const double threshold =
          ratio > 1.0 ? std::acos(std::sqrt(1.0 - 1.0 / (ratio * ratio)) / length) : kPi / 2;
      for (int step = 0; step <= 600; ++step) {
        const double theta =
            step <= 500 ? step * (kPi * 0.53) / 500
                        : threshold * (1.0 + (step % 2 ? 1 : -1) * std::pow(10.0, -(step - 500) / 14.0));
        const Dir normal = test::randomUnit(rng);
        const Dir incident = test::scaled(
            test::incidentAt(normal, test::randomTangent(normal, rng), theta), length);
        const Floats I = test::toFloats(incident), N = test::toFloats(normal);
        const auto allowed =
            cgRefract(test::asVec<Interval>(I), test::asVec<Interval>(N), Interval::point(eta));
        const auto exact = cgRefract(test::asVec<double>(I), test::asVec<double>(N), double(eta));
        const auto strict = cgRefract(test::asVec<float>(I), test::asVec<float>(N), eta);
        const auto fused = cgRefractFused(I, N, eta);
        const Dir If = {I[0], I[1], I[2]}, Nf = {N[0], N[1], N[2]};
        const double cosI = -test::dotOf(If, Nf);
        const double cosT2 = 1.0 - double(eta) * eta * (1.0 - cosI * cosI);
        bool holdsZero = true, holdsNonZero = false;
        for (int j = 0; j < 3; ++j) {
          ASSERT_TRUE(contains(allowed[j], exact[j])) << "double, eta " << eta << ", " << j;
          ASSERT_TRUE(contains(allowed[j], strict[j])) << "float, eta " << eta << ", " << j;
          ASSERT_TRUE(contains(allowed[j], fused[j])) << "fused, eta " << eta << ", " << j;
          holdsZero = holdsZero && contains(allowed[j], 0.0f);
          holdsNonZero = holdsNonZero ||
                         std::max(-allowed[j].lo, allowed[j].hi) > 1e-3 * length;
          // Away from cosT2 = 0, where the square root magnifies rounding,
          // the bound is tight: a ten-thousandth of |I|.
          if (std::fabs(cosT2) > 1e-2) {
            EXPECT_LT(width(allowed[j]), 1e-4 * length) << "eta " << eta << ", " << j;
          }
        }
        if (holdsZero && holdsNonZero) ++eitherWay;
        if (exact[0] == 0.0 && exact[1] == 0.0 && exact[2] == 0.0) ++zero;
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 10000);
  EXPECT_GT(zero, 1000);     // past cosT2 = 0
  EXPECT_GT(eitherWay, 0);   // cosT2 near 0: the union of both outcomes
}

TEST(OracleCgRefract, AnotherEtaRatioFallsOutsideTheIntervals) {
  // Air to glass as printed (1.0003 / 1.5) against vacuum to glass (1 / 1.5):
  // 3e-4 apart, far more than the fp32 error of the formula.
  std::mt19937_64 rng(14);
  const float printed = static_cast<float>(1.0003 / 1.5), other = static_cast<float>(1.0 / 1.5);
  int outside = 0, total = 0;
  for (int step = 1; step <= 400; ++step) {
    const double theta = step * (kPi / 2) / 401;
    const Dir normal = test::randomUnit(rng);
    const Floats I = test::toFloats(
        test::scaled(test::incidentAt(normal, test::randomTangent(normal, rng), theta), 3.0));
    const Floats N = test::toFloats(normal);
    const auto allowed =
        cgRefract(test::asVec<Interval>(I), test::asVec<Interval>(N), Interval::point(printed));
    const auto moved = cgRefract(test::asVec<float>(I), test::asVec<float>(N), other);
    bool any = false;
    for (int j = 0; j < 3; ++j) any = any || !contains(allowed[j], moved[j]);
    outside += any;
    ++total;
  }
  EXPECT_EQ(outside, total);
}

}  // namespace
}  // namespace snell
