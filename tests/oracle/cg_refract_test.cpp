// The Cg Tutorial's refract() (section 7.3.2) as the oracle writes it,
// against the optics it stands for and against GLSL's built-in: Snell's law
// for a unit I, zero exactly where cosT2 <= 0 (cosT2 == 0 included, where
// GLSL's refract() returns the grazing ray), and intervals that hold the
// double, strict float and fused float evaluations, with I of any length.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
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

// The same at the critical angle of glass to air: a unit incident ray whose
// fp32 cosT2 rounds to 0 exactly. The tutorial's float result is zero, GLSL's
// the unit ray along the surface.
TEST(OracleCgRefract, AtTheCriticalAngleGlslGivesTheGrazingRayWhereTheTutorialGivesZero) {
  const float eta = static_cast<float>(1.5 / 1.0003);
  const Floats N = {0.0f, 1.0f, 0.0f};
  float c = static_cast<float>(std::sqrt(1.0 - 1.0 / (double(eta) * eta)));
  c = std::nextafter(c, 0.0f);
  c = std::nextafter(c, 0.0f);
  int tried = 0;
  while (1.0f - eta * eta * (1.0f - c * c) != 0.0f && tried < 64) {
    c = std::nextafter(c, 1.0f);
    ++tried;
  }
  ASSERT_LT(tried, 64) << "no float cosine near the critical angle makes cosT2 exactly 0";
  const Floats I = {std::sqrt(1.0f - c * c), -c, 0.0f};
  const auto tutorial = cgRefract(test::asVec<float>(I), test::asVec<float>(N), eta);
  const auto glsl = glsl::refract(test::asVec<float>(I), test::asVec<float>(N), eta);
  for (int k = 0; k < 3; ++k) EXPECT_EQ(tutorial[k], 0.0f) << k;
  EXPECT_NEAR(glsl[0], 1.0f, 1e-3f);  // along the surface, in the plane of incidence
  EXPECT_NEAR(glsl[1], 0.0f, 1e-3f);
  EXPECT_EQ(glsl[2], 0.0f);
  const auto allowed =
      cgRefract(test::asVec<Interval>(I), test::asVec<Interval>(N), Interval::point(eta));
  for (int k = 0; k < 3; ++k) {
    EXPECT_TRUE(contains(allowed[k], tutorial[k])) << k;
    EXPECT_TRUE(contains(allowed[k], glsl[k])) << k;
  }
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
      for (int step = 0; step <= 500; ++step) {
        const double theta = step * (kPi * 0.53) / 500;  // to just past grazing
        const Dir normal = test::randomUnit(rng);
        const Dir incident = test::scaled(
            test::incidentAt(normal, test::randomTangent(normal, rng), theta), length);
        const Floats I = test::toFloats(incident), N = test::toFloats(normal);
        const auto allowed =
            cgRefract(test::asVec<Interval>(I), test::asVec<Interval>(N), Interval::point(eta));
        const auto exact = cgRefract(test::asVec<double>(I), test::asVec<double>(N), double(eta));
        const auto strict = cgRefract(test::asVec<float>(I), test::asVec<float>(N), eta);
        const auto fused = cgRefractFused(I, N, eta);
        bool holdsZero = true, holdsNonZero = false;
        for (int j = 0; j < 3; ++j) {
          ASSERT_TRUE(contains(allowed[j], exact[j])) << "double, eta " << eta << ", " << j;
          ASSERT_TRUE(contains(allowed[j], strict[j])) << "float, eta " << eta << ", " << j;
          ASSERT_TRUE(contains(allowed[j], fused[j])) << "fused, eta " << eta << ", " << j;
          holdsZero = holdsZero && contains(allowed[j], 0.0f);
          holdsNonZero = holdsNonZero || std::fabs(strict[j]) > 1e-3 * length;
          if (!holdsZero) {
            // Away from cosT2 = 0 the bound is tight: well under a thousandth of |I|.
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
