// The Interval instantiation of reflect/refract holds every result the
// others give: the double value, the strict float value, and float
// evaluations an implementation may legally use instead (fused
// multiply-adds, another summation order). Bounds are floats and tight: the
// float one step beyond either bound is not allowed.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "test_geometry.h"

namespace snell {
namespace {

using test::Dir;
constexpr double kPi = 3.14159265358979323846;
constexpr float kFloatInf = std::numeric_limits<float>::infinity();

using Floats = std::array<float, 3>;

// reflect and refract as a fusing compiler may emit them: dot summed from
// the last term with fma, the final steps fused.
glsl::vec3<float> reflectFused(const Floats& I, const Floats& N) {
  const float d = std::fma(N[0], I[0], std::fma(N[1], I[1], N[2] * I[2]));
  glsl::vec3<float> r;
  for (int j = 0; j < 3; ++j) r[j] = std::fma(-2.0f * d, N[j], I[j]);
  return r;
}

glsl::vec3<float> refractFused(const Floats& I, const Floats& N, float eta) {
  const float d = std::fma(N[0], I[0], std::fma(N[1], I[1], N[2] * I[2]));
  const float k = std::fma(-eta * eta, std::fma(-d, d, 1.0f), 1.0f);
  glsl::vec3<float> r;
  if (k < 0.0f) return r;
  const float b = std::fma(eta, d, std::sqrt(k));
  for (int j = 0; j < 3; ++j) r[j] = std::fma(eta, I[j], -b * N[j]);
  return r;
}

// Every bound is a float, is itself allowed, and the next float out is not.
void expectTightFloatBounds(const Interval& r) {
  ASSERT_FALSE(r.undefined);
  ASSERT_TRUE(isFloat(r.lo) && isFloat(r.hi)) << r.lo << " " << r.hi;
  const float lo = static_cast<float>(r.lo);
  const float hi = static_cast<float>(r.hi);
  EXPECT_TRUE(contains(r, lo));
  EXPECT_TRUE(contains(r, hi));
  EXPECT_FALSE(contains(r, std::nextafter(lo, -kFloatInf)));
  EXPECT_FALSE(contains(r, std::nextafter(hi, kFloatInf)));
}

struct Counts {
  int reflect = 0;
  int refract = 0;
  int totalInternal = 0;
  int straddling = 0;
};

// One incident/normal pair through all three number types.
void checkPair(const Floats& I, const Floats& N, float eta, Counts& counts) {
  const auto reflectAllowed = glsl::reflect(test::asVec<Interval>(I), test::asVec<Interval>(N));
  const auto reflectExact = glsl::reflect(test::asVec<double>(I), test::asVec<double>(N));
  const auto reflectStrict = glsl::reflect(test::asVec<float>(I), test::asVec<float>(N));
  const auto reflectOther = reflectFused(I, N);
  for (int j = 0; j < 3; ++j) {
    ASSERT_TRUE(contains(reflectAllowed[j], reflectExact[j])) << "reflect double, component " << j;
    ASSERT_TRUE(contains(reflectAllowed[j], reflectStrict[j])) << "reflect float, component " << j;
    ASSERT_TRUE(contains(reflectAllowed[j], reflectOther[j])) << "reflect fused, component " << j;
    expectTightFloatBounds(reflectAllowed[j]);
  }
  ++counts.reflect;

  const auto refractAllowed =
      glsl::refract(test::asVec<Interval>(I), test::asVec<Interval>(N), Interval::point(eta));
  const auto refractExact =
      glsl::refract(test::asVec<double>(I), test::asVec<double>(N), double(eta));
  const auto refractStrict = glsl::refract(test::asVec<float>(I), test::asVec<float>(N), eta);
  const auto refractOther = refractFused(I, N, eta);
  for (int j = 0; j < 3; ++j) {
    ASSERT_TRUE(contains(refractAllowed[j], refractExact[j]))
        << "refract double, component " << j << " eta " << eta;
    ASSERT_TRUE(contains(refractAllowed[j], refractStrict[j]))
        << "refract float, component " << j << " eta " << eta;
    ASSERT_TRUE(contains(refractAllowed[j], refractOther[j]))
        << "refract fused, component " << j << " eta " << eta;
    expectTightFloatBounds(refractAllowed[j]);
  }
  ++counts.refract;
  const bool zero = refractAllowed[0].lo == 0 && refractAllowed[0].hi == 0 &&
                    refractAllowed[1].lo == 0 && refractAllowed[1].hi == 0 &&
                    refractAllowed[2].lo == 0 && refractAllowed[2].hi == 0;
  if (zero) ++counts.totalInternal;
  bool allowsZero = true;
  bool allowsARay = false;
  for (int j = 0; j < 3; ++j) {
    allowsZero = allowsZero && contains(refractAllowed[j], 0.0f);
    allowsARay = allowsARay || std::fmax(-refractAllowed[j].lo, refractAllowed[j].hi) > 0.5;
  }
  if (allowsZero && allowsARay) ++counts.straddling;
}

TEST(OracleBuiltinInterval, HoldsDoubleFloatAndFusedResultsForRandomUnitVectors) {
  std::mt19937_64 rng(31);
  std::uniform_real_distribution<float> eta(0.5f, 2.0f);
  Counts counts;
  for (int trial = 0; trial < 20000; ++trial) {
    // Any pair of unit vectors, facing or not.
    checkPair(test::toFloats(test::randomUnit(rng)), test::toFloats(test::randomUnit(rng)),
              eta(rng), counts);
    if (HasFatalFailure()) return;
  }
  EXPECT_GT(counts.totalInternal, 0);  // the sample covers both branches
}

TEST(OracleBuiltinInterval, HoldsAllResultsOverAngleSweepsUpToGrazing) {
  std::mt19937_64 rng(37);
  Counts counts;
  for (float eta : {0.66f, 0.75f, 1.0f / 1.33f, 1.33f, 1.5f}) {
    for (int plane = 0; plane < 20; ++plane) {
      const Dir normal = test::randomUnit(rng);
      const Dir tangent = test::randomTangent(normal, rng);
      for (int step = 0; step <= 1000; ++step) {
        // Denser towards grazing, and grazing itself.
        const double theta = (kPi / 2) * std::sin(step * (kPi / 2) / 1000);
        checkPair(test::toFloats(test::incidentAt(normal, tangent, theta)), test::toFloats(normal),
                  eta, counts);
        if (HasFatalFailure()) return;
      }
    }
  }
  EXPECT_GT(counts.totalInternal, 0);
}

TEST(OracleBuiltinInterval, NearTheCriticalAngleHoldsBothBranches) {
  std::mt19937_64 rng(41);
  Counts counts;
  const float eta = 1.5f;
  const double critical = std::asin(1.0 / eta);
  for (int plane = 0; plane < 50; ++plane) {
    const Dir normal = test::randomUnit(rng);
    const Dir tangent = test::randomTangent(normal, rng);
    for (int step = -200; step <= 200; ++step) {
      const double theta = critical + step * 1e-8;
      checkPair(test::toFloats(test::incidentAt(normal, tangent, theta)), test::toFloats(normal),
                eta, counts);
      if (HasFatalFailure()) return;
    }
  }
  // Within ~1e-6 rad of the critical angle an implementation may return
  // either the zero vector or a grazing ray: both must be allowed.
  EXPECT_GT(counts.straddling, 0);
  EXPECT_GT(counts.totalInternal, 0);
}

TEST(OracleBuiltinInterval, PastTheCriticalAngleOnlyTheZeroVectorIsAllowed) {
  const float eta = 1.5f;
  const Dir normal = {0.0, 0.0, 1.0};
  const Dir tangent = {1.0, 0.0, 0.0};
  const auto I = test::toFloats(test::incidentAt(normal, tangent, std::asin(1.0 / eta) + 1e-3));
  const auto allowed =
      glsl::refract(test::asVec<Interval>(I), test::asVec<Interval>(test::toFloats(normal)),
                    Interval::point(eta));
  for (int j = 0; j < 3; ++j) {
    EXPECT_EQ(allowed[j].lo, 0.0);
    EXPECT_EQ(allowed[j].hi, 0.0);
  }
}

}  // namespace
}  // namespace snell
