// The exact Fresnel equations and Schlick's approximation against closed
// forms: normal incidence, Brewster's angle, the critical angle, and energy
// conservation with the transmittance computed here from the transmission
// amplitudes (not as 1 - R).
#include "oracle/physics/fresnel.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "core/errors.h"
#include "oracle/physics/interface_angles.h"

namespace snell::physics {
namespace {

constexpr double kRadiansPerDegree = std::numbers::pi / 180.0;

double cosOfDegrees(double degrees) { return std::cos(degrees * kRadiansPerDegree); }

TEST(Fresnel, NormalIncidenceIsTheSquaredIndexRatio) {
  for (const double n : {1.333, 1.5, 1.7, 2.42}) {
    const double expected = std::pow((n - 1.0) / (n + 1.0), 2);
    for (const auto& [n1, n2] : {std::pair{1.0, n}, std::pair{n, 1.0}}) {
      const FresnelReflectance r = fresnelExact(1.0, n1, n2);
      EXPECT_NEAR(r.unpolarised, expected, 1e-15) << n1 << " -> " << n2;
      EXPECT_NEAR(r.s, r.p, 1e-15) << "no plane of incidence at normal incidence";
      EXPECT_NEAR(fresnelSchlick(1.0, n1, n2), expected, 1e-15);
    }
  }
  // The check tells indices apart: 1.5 and 1.52 differ by far more than it allows.
  EXPECT_GT(std::fabs(fresnelExact(1.0, 1.0, 1.52).unpolarised - std::pow(0.5 / 2.5, 2)), 1e-4);
}

// Hecht's worked case, glass of 1.5 at 45 degrees from air: Rs = 0.0920,
// Rp = 0.00847 (by hand from the amplitude formulas, to the digits shown).
// Equal indices are no interface: nothing is reflected at any angle, even
// where cos_i squared underflows (it gave 1 below cos_i = 1e-154). At
// cos_i = 0 exactly the ray skims the surface: full reflection, the limit
// kept there.
TEST(Fresnel, EqualIndicesReflectNothing) {
  for (const double cosine : {1.0, 0.5, 1e-9, 1e-160, 1e-300, 5e-324}) {
    const FresnelReflectance r = fresnelExact(cosine, 1.5, 1.5);
    EXPECT_EQ(r.unpolarised, 0.0) << cosine;
    EXPECT_EQ(r.s, 0.0) << cosine;
    EXPECT_EQ(r.p, 0.0) << cosine;
  }
  EXPECT_EQ(fresnelExact(0.0, 1.5, 1.5).unpolarised, 1.0);
  EXPECT_GT(fresnelExact(1e-300, 1.5, 1.5000001).unpolarised, 0.99);  // an interface: grazing
}

// Reflectance depends on the ratio of the indices only: indices near the
// double range give what 10 and 1 give (their squares overflowed to a NaN,
// which read as total reflection).
TEST(Fresnel, HugeIndicesGiveWhatTheirRatioGives) {
  for (const double cosine : {0.999, 0.5, 0.1}) {
    EXPECT_NEAR(fresnelExact(cosine, 1e200, 1e199).unpolarised,
                fresnelExact(cosine, 10.0, 1.0).unpolarised, 1e-15)
        << cosine;
    EXPECT_NEAR(fresnelExact(cosine, 1.0e308, 1.7e308).unpolarised,
                fresnelExact(cosine, 1.0, 1.7).unpolarised, 1e-15)
        << cosine;
  }
  EXPECT_NEAR(normalIncidenceReflectance(1.0e308, 1.7e308), normalIncidenceReflectance(1.0, 1.7),
              1e-15);
}

TEST(Fresnel, GlassAtFortyFiveDegrees) {
  const FresnelReflectance r = fresnelExact(cosOfDegrees(45.0), 1.0, 1.5);
  EXPECT_NEAR(r.s, 0.0920, 5e-5);
  EXPECT_NEAR(r.p, 0.00847, 5e-6);
  EXPECT_FALSE(r.totalInternalReflection);
}

TEST(Fresnel, ParallelReflectanceVanishesAtBrewstersAngle) {
  for (const auto& [n1, n2] :
       {std::pair{1.0, 1.5}, std::pair{1.5, 1.0}, std::pair{1.0, 1.333}, std::pair{1.333, 1.7}}) {
    const double brewster = brewsterAngleDegrees(n1, n2);
    EXPECT_NEAR(std::tan(brewster * kRadiansPerDegree), n2 / n1, 1e-14);
    const FresnelReflectance at = fresnelExact(cosOfDegrees(brewster), n1, n2);
    EXPECT_LT(at.p, 1e-28) << n1 << " -> " << n2;
    EXPECT_GT(at.s, 1e-3) << "only p vanishes";
    // One degree off, Rp is plainly not zero: the check can fail.
    EXPECT_GT(fresnelExact(cosOfDegrees(brewster + 1.0), n1, n2).p, 1e-6);
  }
}

TEST(Fresnel, TotalInternalReflectionFromTheCriticalAngleOn) {
  const double n1 = 1.5, n2 = 1.0;
  const double critical = criticalAngleDegrees(n1, n2);
  EXPECT_NEAR(critical, 41.8103, 5e-5);  // asin(1 / 1.5), to four decimals
  for (const double past : {1e-9, 1e-3, 1.0, 20.0, 48.0}) {
    const FresnelReflectance r = fresnelExact(cosOfDegrees(critical + past), n1, n2);
    EXPECT_EQ(r.unpolarised, 1.0) << past;
    EXPECT_TRUE(r.totalInternalReflection);
  }
  // At the angle itself cos_t is 0 up to rounding: R = 1 - O(sqrt(eps)).
  EXPECT_NEAR(fresnelExact(cosOfDegrees(critical), n1, n2).unpolarised, 1.0, 1e-6);
  // Continuous from below: 1 - R shrinks as the square root of the distance
  // to the critical angle (cos_t ~ sqrt(theta_c - theta)), so each step 100
  // times closer shrinks it 10 times.
  const double criticalRadians = critical * kRadiansPerDegree;
  double previousGap = 1.0;
  for (const double before : {1e-4, 1e-6, 1e-8, 1e-10}) {
    const FresnelReflectance r = fresnelExact(std::cos(criticalRadians - before), n1, n2);
    EXPECT_FALSE(r.totalInternalReflection);
    const double gap = 1.0 - r.unpolarised;
    EXPECT_GT(gap, 0.0);
    if (before < 1e-4) {
      EXPECT_NEAR(previousGap / gap, 10.0, 0.5) << before;
    }
    previousGap = gap;
  }
  EXPECT_LT(previousGap, 1e-4);
}

// T from the transmission amplitudes t_s = 2 n1 c_i / (n1 c_i + n2 c_t),
// t_p = 2 n1 c_i / (n2 c_i + n1 c_t), scaled by the beam's change of cross
// section and speed, n2 c_t / (n1 c_i).
TEST(Fresnel, ReflectedAndTransmittedEnergySumToOne) {
  int checked = 0;
  for (const auto& [n1, n2] : {std::pair{1.0, 1.5}, std::pair{1.5, 1.0}, std::pair{1.0, 2.42},
                               std::pair{1.333, 1.5168}, std::pair{1.7, 1.333}}) {
    for (int k = 1; k <= 90; ++k) {
      const double ci = std::cos((k - 0.5) * kRadiansPerDegree);
      const FresnelReflectance r = fresnelExact(ci, n1, n2);
      if (r.totalInternalReflection) continue;
      const double sinT = n1 / n2 * std::sqrt(1.0 - ci * ci);
      const double ct = std::sqrt(1.0 - sinT * sinT);
      const double ts = 2.0 * n1 * ci / (n1 * ci + n2 * ct);
      const double tp = 2.0 * n1 * ci / (n2 * ci + n1 * ct);
      const double beam = n2 * ct / (n1 * ci);
      EXPECT_NEAR(r.s + beam * ts * ts, 1.0, 1e-12) << n1 << " -> " << n2 << " at " << k;
      EXPECT_NEAR(r.p + beam * tp * tp, 1.0, 1e-12) << n1 << " -> " << n2 << " at " << k;
      EXPECT_NEAR(r.unpolarised + r.transmitted(), 1.0, 0.0);
      ++checked;
    }
  }
  EXPECT_GT(checked, 300);
  // Swapping Rs and Rp breaks the sum: the comparison can fail.
  const FresnelReflectance r = fresnelExact(cosOfDegrees(60.0), 1.0, 1.5);
  const double ct = std::sqrt(1.0 - std::pow(std::sin(60.0 * kRadiansPerDegree) / 1.5, 2));
  const double ts = 2.0 * 0.5 / (0.5 + 1.5 * ct);
  EXPECT_GT(std::fabs(r.p + 1.5 * ct / 0.5 * ts * ts - 1.0), 1e-3);
}

TEST(Fresnel, SchlickAgreesAtTheEndsAndNotInBetween) {
  EXPECT_DOUBLE_EQ(fresnelSchlick(0.0, 1.0, 1.5), 1.0);
  const double middle = cosOfDegrees(70.0);
  const double gap =
      std::fabs(fresnelSchlick(middle, 1.0, 1.5) - fresnelExact(middle, 1.0, 1.5).unpolarised);
  EXPECT_GT(gap, 1e-3) << "an approximation, not the equations";
  EXPECT_LT(gap, 0.05);
}

// From the dense side Schlick must use the angle in the less dense medium:
// then it is reciprocal (same R both ways along a path) and 1 under total
// internal reflection; plain Schlick with cos_i is neither.
TEST(Fresnel, SchlickOnTheDenseSideUsesTheTransmittedCosine) {
  const double n1 = 1.5, n2 = 1.0;
  for (const double degrees : {0.0, 10.0, 25.0, 40.0}) {
    const double ci = cosOfDegrees(degrees);
    const double sinT = n1 / n2 * std::sin(degrees * kRadiansPerDegree);
    const double ct = std::sqrt(1.0 - sinT * sinT);
    EXPECT_NEAR(fresnelSchlickDenseSide(ci, n1, n2), fresnelSchlick(ct, n2, n1), 1e-14);
    EXPECT_NEAR(fresnelSchlickDenseSide(ct, n2, n1), fresnelSchlick(ct, n2, n1), 0.0)
        << "from the less dense side it is plain Schlick";
  }
  EXPECT_EQ(fresnelSchlickDenseSide(cosOfDegrees(45.0), n1, n2), 1.0);
  EXPECT_LT(fresnelSchlick(cosOfDegrees(45.0), n1, n2), 0.5);
}

TEST(Fresnel, BadInputIsRefused) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(fresnelExact(1.2, 1.0, 1.5), UsageError);
  EXPECT_THROW(fresnelExact(-0.1, 1.0, 1.5), UsageError);
  EXPECT_THROW(fresnelExact(nan, 1.0, 1.5), UsageError);
  EXPECT_THROW(fresnelExact(0.5, 0.0, 1.5), UsageError);
  EXPECT_THROW(fresnelExact(0.5, 1.0, -1.5), UsageError);
  EXPECT_THROW(fresnelExact(0.5, std::numeric_limits<double>::infinity(), 1.5), UsageError);
  EXPECT_THROW(fresnelSchlick(1.5, 1.0, 1.5), UsageError);
  EXPECT_THROW(fresnelSchlickDenseSide(0.5, 1.0, nan), UsageError);
}

}  // namespace
}  // namespace snell::physics
