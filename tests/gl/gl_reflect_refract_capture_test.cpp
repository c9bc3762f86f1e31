// Captures reflect() and refract() for a few hundred inputs through
// transform feedback and compares them with the defining formulas in double.
#include <gtest/gtest.h>

#include <array>
#include <cfloat>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "backends/gl/gl_backend.h"
#include "gl_test_jobs.h"

namespace snell {
namespace {

using Vec3 = std::array<double, 3>;

double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

Vec3 reflectExact(const Vec3& i, const Vec3& n) {
  const double d = dot(n, i);
  return {i[0] - 2 * d * n[0], i[1] - 2 * d * n[1], i[2] - 2 * d * n[2]};
}

double refractK(const Vec3& i, const Vec3& n, double eta) {
  const double d = dot(n, i);
  return 1 - eta * eta * (1 - d * d);
}

Vec3 refractExact(const Vec3& i, const Vec3& n, double eta) {
  const double k = refractK(i, n, eta);
  if (k < 0) return {0, 0, 0};
  const double d = dot(n, i);
  const double s = eta * d + std::sqrt(k);
  return {eta * i[0] - s * n[0], eta * i[1] - s * n[1], eta * i[2] - s * n[2]};
}

// The shader text is generated from the outputs it writes, the way a probe
// for `snell eval` is.
std::string probeShader(const std::vector<std::string>& assignments) {
  std::string text =
      "#version 140\n"
      "in vec3 I;\n"
      "in vec3 N;\n"
      "in float eta;\n"
      "out vec3 Reflected;\n"
      "out vec3 Refracted;\n"
      "void main() {\n";
  for (const auto& line : assignments) text += "  " + line + ";\n";
  return text + "  gl_Position = vec4(0.0);\n}\n";
}

struct Inputs {
  std::vector<float> incident, normal, eta;
  std::size_t count() const { return eta.size(); }
  Vec3 incidentAt(std::size_t v) const { return {incident[3 * v], incident[3 * v + 1], incident[3 * v + 2]}; }
  Vec3 normalAt(std::size_t v) const { return {normal[3 * v], normal[3 * v + 1], normal[3 * v + 2]}; }
};

// Unit normals spread over the sphere (Fibonacci lattice), incidence angles
// from normal to near-grazing, and the listings' ratios on both sides of 1,
// so that both refraction and total internal reflection occur. Samples with
// |k| < 0.25 are left out: near the critical angle, fp32 cancellation in k
// makes sqrt(k) arbitrarily far from the double value in ULPs, and judging
// that is the oracle's interval job, not this test's.
Inputs makeInputs(int candidates) {
  const double golden = std::numbers::pi * (3 - std::sqrt(5.0));
  const float ratios[] = {0.66f, 1 / 1.33f, 1 / 1.5f, 1.0f, 1.33f, 1.5f};
  Inputs in;
  for (int c = 0; c < candidates; ++c) {
    const double z = 1 - 2 * (c + 0.5) / candidates;
    const double r = std::sqrt(1 - z * z);
    const Vec3 n{r * std::cos(golden * c), r * std::sin(golden * c), z};
    // A tangent: any unit vector orthogonal to n.
    Vec3 t = std::abs(n[2]) < 0.9 ? Vec3{-n[1], n[0], 0} : Vec3{0, -n[2], n[1]};
    const double tl = std::sqrt(dot(t, t));
    for (double& x : t) x /= tl;
    const double theta = (c % 89) * std::numbers::pi / 180;  // 0..88 degrees
    const Vec3 i{-std::cos(theta) * n[0] + std::sin(theta) * t[0],
                 -std::cos(theta) * n[1] + std::sin(theta) * t[1],
                 -std::cos(theta) * n[2] + std::sin(theta) * t[2]};
    const float eta = ratios[c % 6];
    const Vec3 fi{float(i[0]), float(i[1]), float(i[2])};
    const Vec3 fn{float(n[0]), float(n[1]), float(n[2])};
    if (std::abs(refractK(fi, fn, eta)) < 0.25) continue;
    for (int a = 0; a < 3; ++a) {
      in.incident.push_back(float(i[a]));
      in.normal.push_back(float(n[a]));
    }
    in.eta.push_back(eta);
  }
  return in;
}

// This is a smoke test of the plumbing (attributes in, outputs split per
// name and vertex), not of precision; the spec intervals live in the
// oracle. Each component is a handful of fp32 operations on values no larger
// than 2 (each rounding off by at most 1 ULP of 2, i.e. 2*FLT_EPSILON), and
// with |k| >= 0.25 sqrt(k) amplifies k's error by at most 1; so 8 ULPs of 2.0
// bounds honest fp32 rounding, while a swapped argument, a wrong sign or a
// varying read from the wrong offset errs by more than 0.01.
constexpr double kTolerance = 8 * 2 * FLT_EPSILON;

class GlReflectRefractCapture : public ::testing::Test {
 protected:
  void SetUp() override {
    inputs_ = makeInputs(600);
    job_.program = gltest::vertexOnly(probeShader(
        {"Reflected = reflect(I, N)", "Refracted = refract(I, N, eta)"}));
    gltest::addAttribute(job_, gltest::attribute("I", 3, inputs_.incident));
    gltest::addAttribute(job_, gltest::attribute("N", 3, inputs_.normal));
    gltest::addAttribute(job_, gltest::attribute("eta", 1, inputs_.eta));
    job_.varyings = {"Reflected", "Refracted"};
    job_.vertexCount = inputs_.count();
  }

  Inputs inputs_;
  CaptureJob job_;
};

TEST_F(GlReflectRefractCapture, InputsCoverRefractionAndTotalInternalReflection) {
  int internal = 0;
  for (std::size_t v = 0; v < inputs_.count(); ++v)
    internal += refractK(inputs_.incidentAt(v), inputs_.normalAt(v), inputs_.eta[v]) < 0;
  EXPECT_GE(inputs_.count(), 300u);
  EXPECT_GE(internal, 20);
  EXPECT_GE(static_cast<int>(inputs_.count()) - internal, 200);
}

TEST_F(GlReflectRefractCapture, MatchesDefiningFormulasInDouble) {
  auto backend = makeGlBackend({});
  const CaptureOutcome outcome = backend->captureVertexOutputs(job_);
  ASSERT_TRUE(outcome.compile.ok) << outcome.compile.log;
  ASSERT_EQ(outcome.varyings.size(), 2u);
  EXPECT_EQ(outcome.varyings[0].name, "Reflected");
  EXPECT_EQ(outcome.varyings[1].name, "Refracted");
  const CapturedVarying& reflected = gltest::varyingNamed(outcome, "Reflected");
  const CapturedVarying& refracted = gltest::varyingNamed(outcome, "Refracted");
  ASSERT_EQ(reflected.components, 3);
  ASSERT_EQ(refracted.components, 3);
  ASSERT_EQ(reflected.data.size(), 3 * inputs_.count());
  ASSERT_EQ(refracted.data.size(), 3 * inputs_.count());

  for (std::size_t v = 0; v < inputs_.count(); ++v) {
    const Vec3 i = inputs_.incidentAt(v);
    const Vec3 n = inputs_.normalAt(v);
    const Vec3 r = reflectExact(i, n);
    const Vec3 t = refractExact(i, n, inputs_.eta[v]);
    const bool internal = refractK(i, n, inputs_.eta[v]) < 0;
    for (int a = 0; a < 3; ++a) {
      EXPECT_NEAR(reflected.data[3 * v + a], r[a], kTolerance) << "vertex " << v << " axis " << a;
      // The spec says refract() returns exactly 0 on total internal reflection.
      if (internal)
        EXPECT_EQ(refracted.data[3 * v + a], 0.0f) << "vertex " << v << " axis " << a;
      else
        EXPECT_NEAR(refracted.data[3 * v + a], t[a], kTolerance) << "vertex " << v << " axis " << a;
    }
  }
}

TEST_F(GlReflectRefractCapture, VaryingOrderFollowsTheJob) {
  job_.varyings = {"Refracted", "Reflected"};
  auto backend = makeGlBackend({});
  const CaptureOutcome outcome = backend->captureVertexOutputs(job_);
  ASSERT_TRUE(outcome.compile.ok) << outcome.compile.log;
  ASSERT_EQ(outcome.varyings.size(), 2u);
  EXPECT_EQ(outcome.varyings[0].name, "Refracted");
  const Vec3 expected = reflectExact(inputs_.incidentAt(0), inputs_.normalAt(0));
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(outcome.varyings[1].data[a], expected[a], kTolerance);
}

}  // namespace
}  // namespace snell
