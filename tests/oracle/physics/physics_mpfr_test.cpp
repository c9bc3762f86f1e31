// The four functions `snell eval` answers from the physics reference
// (fresnel, ior, critical_angle, brewster_angle), each against a 256-bit
// MPFR evaluation of the same formula from the same double inputs, over a
// grid: within 1e-12 relative. The grid covers the indices of real media
// (air, water, crown and flint glasses, diamond), every incidence in
// quarter-degree steps plus points within 1e-3 to 1e-12 of the critical
// angle, and each fit's whole wavelength range.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "high_precision/mpfr_number.h"
#include "oracle/physics/fresnel.h"
#include "oracle/physics/interface_angles.h"
#include "oracle/physics/sellmeier.h"

namespace snell::physics {
namespace {

using test::Mp;

constexpr double kTolerance = 1e-12;
const std::vector<double> kIndices = {1.0, 1.2, 1.333, 1.4, 1.5, 1.5168, 1.7, 2.0, 2.42};

struct Worst {
  double relative = 0.0;
  std::string where;
  int compared = 0;

  void see(double value, const Mp& exact, const std::string& what) {
    const double e = exact.toDouble();
    const double r = e == 0.0 ? std::fabs(value) : std::fabs(value - e) / std::fabs(e);
    ++compared;
    if (!(r <= relative)) relative = r, where = what;
  }
};

Mp mp(double x) { return Mp(x); }

Mp asinMp(const Mp& x) { return test::apply(mpfr_asin, x); }
Mp atan2Mp(const Mp& y, const Mp& x) { return test::apply(mpfr_atan2, y, x); }
Mp degrees(const Mp& radians) {
  Mp pi;
  mpfr_const_pi(pi.get(), MPFR_RNDN);
  return radians * mp(180.0) / pi;
}

// Exact unpolarised reflectance, and Schlick, in 256 bits.
Mp exactFresnel(double cosI, double n1, double n2) {
  const Mp ci = mp(cosI), a = mp(n1), b = mp(n2), one = mp(1.0);
  const Mp eta = a / b;
  const Mp k = one - eta * eta * (one - ci * ci);
  if (k < mp(0.0)) return one;
  const Mp ct = test::sqrt(k);
  const Mp rs = (a * ci - b * ct) / (a * ci + b * ct);
  const Mp rp = (b * ci - a * ct) / (b * ci + a * ct);
  return (rs * rs + rp * rp) / mp(2.0);
}
Mp schlick(const Mp& cosine, double n1, double n2) {
  const Mp r = (mp(n1) - mp(n2)) / (mp(n1) + mp(n2));
  const Mp r0 = r * r, m = mp(1.0) - cosine;
  return r0 + (mp(1.0) - r0) * m * m * m * m * m;
}
Mp schlickDenseSide(double cosI, double n1, double n2) {
  if (n1 <= n2) return schlick(mp(cosI), n1, n2);
  const Mp eta = mp(n1) / mp(n2), ci = mp(cosI);
  const Mp k = mp(1.0) - eta * eta * (mp(1.0) - ci * ci);
  if (k < mp(0.0)) return mp(1.0);
  return schlick(test::sqrt(k), n1, n2);
}

std::vector<double> cosines(double n1, double n2) {
  std::vector<double> out;
  for (int q = 0; q <= 360; ++q) out.push_back(std::cos(q * 0.25 * std::numbers::pi / 180.0));
  out.back() = 0.0;
  if (n1 > n2) {
    const double critical = std::sqrt(1.0 - (n2 / n1) * (n2 / n1));
    for (const double d : {1e-3, 1e-6, 1e-9, 1e-12}) {
      out.push_back(critical * (1.0 + d));
      out.push_back(critical * (1.0 - d));
    }
  }
  return out;
}

std::string at(double a, double b, double c) {
  return std::to_string(a) + " " + std::to_string(b) + " " + std::to_string(c);
}

TEST(PhysicsMpfr, FresnelWithin1e12OfMpfr) {
  Worst exact, plain, dense;
  for (const double n1 : kIndices)
    for (const double n2 : kIndices) {
      if (n1 == n2) continue;
      for (const double c : cosines(n1, n2)) {
        exact.see(fresnelExact(c, n1, n2).unpolarised, exactFresnel(c, n1, n2), at(c, n1, n2));
        plain.see(fresnelSchlick(c, n1, n2), schlick(mp(c), n1, n2), at(c, n1, n2));
        dense.see(fresnelSchlickDenseSide(c, n1, n2), schlickDenseSide(c, n1, n2), at(c, n1, n2));
      }
    }
  EXPECT_GT(exact.compared, 20000);
  EXPECT_LE(exact.relative, kTolerance) << "exact, at " << exact.where;
  EXPECT_LE(plain.relative, kTolerance) << "schlick, at " << plain.where;
  EXPECT_LE(dense.relative, kTolerance) << "schlick_dense_side, at " << dense.where;
  std::printf("fresnel worst relative error: exact %.3g (%s), schlick %.3g, dense side %.3g\n",
              exact.relative, exact.where.c_str(), plain.relative, dense.relative);
  // The comparison sees a difference in the 13th digit: the check can fail.
  Worst off;
  off.see(fresnelExact(0.5, 1.0, 1.5).unpolarised * (1.0 + 2e-12), exactFresnel(0.5, 1.0, 1.5),
          "scaled");
  EXPECT_GT(off.relative, kTolerance);
}

TEST(PhysicsMpfr, IorWithin1e12OfMpfr) {
  Worst worst;
  for (const SellmeierGlass* glass : {&nBk7(), &water20C()}) {
    for (int i = 0; i <= 1000; ++i) {
      const double nm = glass->minNm + (glass->maxNm - glass->minNm) * i / 1000.0;
      const Mp um = mp(nm) / mp(1000.0);
      Mp sum = mp(1.0);
      for (const SellmeierTerm& t : glass->terms)
        sum = sum + mp(t.b) * um * um / (um * um - mp(t.c));
      worst.see(refractiveIndex(*glass, nm), test::sqrt(sum),
                std::string(glass->name) + " " + std::to_string(nm));
    }
  }
  EXPECT_LE(worst.relative, kTolerance) << worst.where;
  std::printf("ior worst relative error %.3g (%s)\n", worst.relative, worst.where.c_str());
}

TEST(PhysicsMpfr, AnglesWithin1e12OfMpfr) {
  Worst critical, brewster;
  for (const double n1 : kIndices)
    for (const double n2 : kIndices) {
      brewster.see(brewsterAngleDegrees(n1, n2), degrees(atan2Mp(mp(n2), mp(n1))), at(n1, n2, 0));
      if (n1 > n2)
        critical.see(criticalAngleDegrees(n1, n2), degrees(asinMp(mp(n2) / mp(n1))), at(n1, n2, 0));
    }
  // Nearly matched indices, where asin(n2 / n1) is ill-conditioned.
  for (const double gap : {1e-3, 1e-6, 1e-9, 1e-12}) {
    const double n1 = 1.5, n2 = 1.5 * (1.0 - gap);
    critical.see(criticalAngleDegrees(n1, n2), degrees(asinMp(mp(n2) / mp(n1))), at(n1, n2, gap));
  }
  EXPECT_LE(critical.relative, kTolerance) << critical.where;
  EXPECT_LE(brewster.relative, kTolerance) << brewster.where;
  std::printf("critical angle worst %.3g (%s), brewster angle worst %.3g\n", critical.relative,
              critical.where.c_str(), brewster.relative);
}

}  // namespace
}  // namespace snell::physics
