// reflect and refract as the oracle writes them (double and float
// instantiations) against the optics they stand for: Snell's law, equal
// angles of incidence and reflection, total internal reflection past the
// critical angle, and no bending at normal incidence.
#include <gtest/gtest.h>

#include <cmath>

#include "test_geometry.h"

namespace snell {
namespace {

using test::Dir;

glsl::vec3<double> asVec(const Dir& d) { return glsl::vec3<double>(d[0], d[1], d[2]); }

// Angles between a direction and the normal's line, and the side of the
// plane (normal, incident) the direction leans to.
struct Angles {
  double sine;    // |component across the normal|
  double cosine;  // component along -normal
};
Angles anglesOf(const Dir& v, const Dir& normal) {
  const double along = test::dotOf(v, normal);
  const Dir across = test::plus(v, test::scaled(normal, -along));
  return {test::lengthOf(across), -along};
}

constexpr double kPi = 3.14159265358979323846;

TEST(OracleBuiltinClosedForm, RefractObeysSnellsLaw) {
  std::mt19937_64 rng(1);
  for (double eta : {0.66, 0.75, 1.0 / 1.33, 1.2, 1.5}) {
    for (int step = 0; step <= 900; ++step) {
      const double theta = step * (kPi / 2) / 900;  // 0 to grazing
      const Dir normal = test::randomUnit(rng);
      const Dir tangent = test::randomTangent(normal, rng);
      const Dir incident = test::incidentAt(normal, tangent, theta);
      if (eta * std::sin(theta) > 1.0) continue;  // total internal reflection
      const Dir refracted = test::fromVec(glsl::refract(asVec(incident), asVec(normal), eta));
      const Angles t = anglesOf(refracted, normal);
      EXPECT_NEAR(test::lengthOf(refracted), 1.0, 1e-12);
      EXPECT_NEAR(t.sine, eta * std::sin(theta), 1e-12) << "eta " << eta << " theta " << theta;
      EXPECT_GE(t.cosine, -1e-12);  // transmitted: through the surface
      // In the plane of incidence, bent towards the same side as the incident ray.
      EXPECT_NEAR(test::dotOf(refracted, test::crossOf(normal, tangent)), 0.0, 1e-12);
      EXPECT_GE(test::dotOf(refracted, tangent), -1e-12);
    }
  }
}

TEST(OracleBuiltinClosedForm, ReflectGivesEqualAnglesOfIncidenceAndReflection) {
  std::mt19937_64 rng(2);
  for (int step = 0; step <= 900; ++step) {
    const double theta = step * (kPi / 2) / 900;
    const Dir normal = test::randomUnit(rng);
    const Dir tangent = test::randomTangent(normal, rng);
    const Dir incident = test::incidentAt(normal, tangent, theta);
    const Dir reflected = test::fromVec(glsl::reflect(asVec(incident), asVec(normal)));
    const Angles r = anglesOf(reflected, normal);
    EXPECT_NEAR(test::lengthOf(reflected), 1.0, 1e-12);
    EXPECT_NEAR(r.cosine, -std::cos(theta), 1e-12);  // leaves on the incident side
    EXPECT_NEAR(r.sine, std::sin(theta), 1e-12);
    EXPECT_NEAR(test::dotOf(reflected, tangent), std::sin(theta), 1e-12);
  }
}

TEST(OracleBuiltinClosedForm, TotalInternalReflectionStartsExactlyAtTheCriticalAngle) {
  std::mt19937_64 rng(3);
  for (double eta : {1.2, 1.33, 1.5, 2.4}) {
    const double critical = std::asin(1.0 / eta);
    const Dir normal = test::randomUnit(rng);
    const Dir tangent = test::randomTangent(normal, rng);
    const Dir past = test::fromVec(glsl::refract(
        asVec(test::incidentAt(normal, tangent, critical + 1e-9)), asVec(normal), eta));
    const Dir before = test::fromVec(glsl::refract(
        asVec(test::incidentAt(normal, tangent, critical - 1e-9)), asVec(normal), eta));
    EXPECT_EQ(past, (Dir{0.0, 0.0, 0.0})) << "eta " << eta;
    EXPECT_NEAR(test::lengthOf(before), 1.0, 1e-9) << "eta " << eta;
    // Just before the critical angle the ray leaves almost along the surface.
    EXPECT_NEAR(anglesOf(before, normal).sine, 1.0, 1e-5);
  }
}

TEST(OracleBuiltinClosedForm, FloatGivesTheZeroVectorPastTheCriticalAngle) {
  const float eta = 1.5f;
  const double critical = std::asin(1.0 / eta);
  const Dir normal = {0.0, 0.0, 1.0};
  const Dir tangent = {1.0, 0.0, 0.0};
  const auto past = glsl::refract(
      test::asVec<float>(test::toFloats(test::incidentAt(normal, tangent, critical + 1e-3))),
      test::asVec<float>(test::toFloats(normal)), eta);
  EXPECT_EQ(past[0], 0.0f);
  EXPECT_EQ(past[1], 0.0f);
  EXPECT_EQ(past[2], 0.0f);
  const auto before = glsl::refract(
      test::asVec<float>(test::toFloats(test::incidentAt(normal, tangent, critical - 1e-3))),
      test::asVec<float>(test::toFloats(normal)), eta);
  EXPECT_GT(before[0], 0.9f);
}

TEST(OracleBuiltinClosedForm, RefractAtNormalIncidenceDoesNotBend) {
  std::mt19937_64 rng(4);
  for (double eta : {0.66, 1.0, 1.5}) {
    const Dir normal = test::randomUnit(rng);
    const Dir incident = test::scaled(normal, -1.0);
    const Dir refracted = test::fromVec(glsl::refract(asVec(incident), asVec(normal), eta));
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(refracted[k], incident[k], 1e-15);
  }
  // Axis-aligned, every step is exact in float too.
  const auto straight = glsl::refract(glsl::vec3<float>(0.0f, 0.0f, -1.0f),
                                      glsl::vec3<float>(0.0f, 0.0f, 1.0f), 0.66f);
  EXPECT_EQ(straight[0], 0.0f);
  EXPECT_EQ(straight[1], 0.0f);
  EXPECT_EQ(straight[2], -1.0f);
}

}  // namespace
}  // namespace snell
