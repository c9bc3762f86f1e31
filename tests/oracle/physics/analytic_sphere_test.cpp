// The analytic sphere against closed forms: Descartes' deviation angles for
// each number of internal reflections, the Fresnel weights (by Stokes'
// relations every inside hit reflects as much as the entry did), and
// energy conservation with the truncated tail reported.
#include "oracle/physics/analytic_sphere.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/errors.h"
#include "oracle/physics/fresnel.h"

namespace snell::physics {
namespace {

// A ray along -z at height b (the impact parameter, in radii) above the
// centre of a unit sphere: sin(theta_i) = b.
SphereTrace traceAtHeight(double b, double index, int hits, double outside = 1.0) {
  const Sphere sphere{{0.0, 0.0, 0.0}, 1.0, index, outside};
  return traceSphere(sphere, {0.0, b, 5.0}, {0.0, 0.0, -1.0}, {hits, 0.0});
}

double weightSum(const SphereTrace& trace) {
  double sum = 0.0;
  for (const SphereExit& exit : trace.exits) sum += exit.weight;
  return sum;
}

TEST(AnalyticSphere, EnergyIsConservedWithTheTailReported) {
  for (const double n : {1.333, 1.5168, 2.42, 0.75}) {
    for (const double b : {0.0, 0.1, 0.5, 0.8, 0.95, 0.999}) {
      for (const int hits : {0, 1, 2, 5, 12}) {
        const SphereTrace trace = traceAtHeight(b, n, hits);
        EXPECT_NEAR(weightSum(trace) + trace.remaining, 1.0, 1e-14)
            << "n " << n << " b " << b << " hits " << hits;
      }
    }
  }
  // With enough hits the tail is what is left; it shrinks as R^k.
  const SphereTrace shallow = traceAtHeight(0.5, 1.5, 3), deep = traceAtHeight(0.5, 1.5, 6);
  EXPECT_LT(deep.remaining, shallow.remaining * 1e-3);
}

TEST(AnalyticSphere, WeightsAreTheFresnelSeries) {
  const double n = 1.5, b = 0.7;
  const FresnelReflectance entry = fresnelExact(std::sqrt(1.0 - b * b), 1.0, n);
  const double R = entry.unpolarised, T = 1.0 - R;
  const SphereTrace trace = traceAtHeight(b, n, 5);
  ASSERT_EQ(trace.exits.size(), 6u);
  EXPECT_EQ(trace.exits[0].kind, ExitKind::ReflectedAtEntry);
  EXPECT_NEAR(trace.exits[0].weight, R, 1e-15);
  for (int k = 0; k < 5; ++k) {
    const SphereExit& exit = trace.exits[static_cast<std::size_t>(k) + 1];
    EXPECT_EQ(exit.kind, ExitKind::Refracted);
    EXPECT_EQ(exit.internalReflections, k);
    EXPECT_NEAR(exit.weight, T * T * std::pow(R, k), 1e-14) << k;
  }
  EXPECT_NEAR(trace.remaining, T * std::pow(R, 5), 1e-15);
}

// After k internal reflections a ray has turned by
// D = 2 (theta_i - theta_t) + k (pi - 2 theta_t) (Descartes; k = 1 is the
// primary rainbow's path), and the reflected one by pi - 2 theta_i.
TEST(AnalyticSphere, ExitDirectionsFollowDescartes) {
  const double n = 1.333;
  for (const double b : {0.2, 0.6, 0.86, 0.99}) {
    const double thetaI = std::asin(b), thetaT = std::asin(b / n);
    const SphereTrace trace = traceAtHeight(b, n, 4);
    const double incoming[3] = {0.0, 0.0, -1.0};
    const auto turned = [&](const SphereExit& e) {
      return incoming[0] * e.direction.x + incoming[1] * e.direction.y +
             incoming[2] * e.direction.z;
    };
    EXPECT_NEAR(turned(trace.exits[0]), std::cos(std::numbers::pi - 2.0 * thetaI), 1e-12);
    for (int k = 0; k < 4; ++k) {
      const double deviation = 2.0 * (thetaI - thetaT) + k * (std::numbers::pi - 2.0 * thetaT);
      const SphereExit& exit = trace.exits[static_cast<std::size_t>(k) + 1];
      EXPECT_NEAR(turned(exit), std::cos(deviation), 1e-12) << "b " << b << " k " << k;
      EXPECT_NEAR(length(exit.origin), 1.0, 1e-14) << "leaves from the surface";
      // The same path through glass of 1.5 turns plainly otherwise.
      const double glassT = std::asin(b / 1.5);
      const double glass = 2.0 * (thetaI - glassT) + k * (std::numbers::pi - 2.0 * glassT);
      EXPECT_GT(std::fabs(turned(exit) - std::cos(glass)), 1e-4) << "b " << b << " k " << k;
    }
  }
}

// The primary rainbow: over all heights, one internal reflection in water
// turns the light by at least about 138 degrees (Descartes' minimum
// deviation, reached where cos^2 theta_i = (n^2 - 1) / 3).
TEST(AnalyticSphere, PrimaryRainbowAngle) {
  const double n = 1.333;
  double least = 10.0;
  for (int i = 1; i < 2000; ++i) {
    const SphereExit& once = traceAtHeight(i / 2000.0, n, 2).exits[2];
    least = std::min(least, std::acos(-once.direction.z));
  }
  const double cosI = std::sqrt((n * n - 1.0) / 3.0);
  const double thetaI = std::acos(cosI), thetaT = std::asin(std::sin(thetaI) / n);
  const double minimum = std::numbers::pi + 2.0 * thetaI - 4.0 * thetaT;
  // The sampled heights come within 1/4000 of the minimum's, where the
  // deviation is flat to second order.
  EXPECT_NEAR(least, minimum, 1e-5);
  EXPECT_NEAR(minimum * 180.0 / std::numbers::pi, 138.0, 0.1);
}

// A bubble (inside index below outside): past its critical angle the ray
// is totally reflected at entry and nothing enters.
TEST(AnalyticSphere, BubbleReflectsTotallyPastItsCriticalAngle) {
  const SphereTrace grazing = traceAtHeight(0.95, 1.0, 5, 1.333);  // asin 0.95 > asin(1/1.333)
  ASSERT_EQ(grazing.exits.size(), 1u);
  EXPECT_EQ(grazing.exits[0].weight, 1.0);
  EXPECT_EQ(grazing.remaining, 0.0);
  const SphereTrace steep = traceAtHeight(0.3, 1.0, 5, 1.333);
  EXPECT_GT(steep.exits.size(), 2u);
}

TEST(AnalyticSphere, AMissIsTheRayItself) {
  const SphereTrace miss = traceAtHeight(1.2, 1.5, 5);
  ASSERT_EQ(miss.exits.size(), 1u);
  EXPECT_EQ(miss.exits[0].kind, ExitKind::Missed);
  EXPECT_EQ(miss.exits[0].weight, 1.0);
  EXPECT_EQ(miss.exits[0].direction.z, -1.0);
}

TEST(AnalyticSphere, StopsWhereTheEnergyLeftIsBelowTheFloor) {
  const Sphere sphere{{0.0, 0.0, 0.0}, 1.0, 1.5, 1.0};
  const SphereTrace trace = traceSphere(sphere, {0.0, 0.5, 5.0}, {0.0, 0.0, -1.0}, {100, 1e-6});
  EXPECT_LT(trace.remaining, 1e-6);
  EXPECT_LT(trace.internalHits, 100);
  EXPECT_NEAR(weightSum(trace) + trace.remaining, 1.0, 1e-14);
}

TEST(AnalyticSphere, BadInputIsRefused) {
  const Sphere sphere{{0.0, 0.0, 0.0}, 1.0, 1.5, 1.0};
  EXPECT_THROW(traceSphere(sphere, {0, 0, 5}, {0, 0, 0}), UsageError);
  EXPECT_THROW(traceSphere({{0, 0, 0}, -1.0, 1.5, 1.0}, {0, 0, 5}, {0, 0, -1}), UsageError);
  EXPECT_THROW(traceSphere({{0, 0, 0}, 1.0, 0.0, 1.0}, {0, 0, 5}, {0, 0, -1}), UsageError);
  EXPECT_THROW(traceSphere(sphere, {0, 0, 5}, {0, 0, -1}, {-1, 0.0}), UsageError);
}

}  // namespace
}  // namespace snell::physics
