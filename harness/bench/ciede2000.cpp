#include "bench/ciede2000.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace snell::bench {
namespace {

constexpr double kPi = std::numbers::pi;
double degrees(double radians) { return radians * 180.0 / kPi; }
double radians(double degrees) { return degrees * kPi / 180.0; }
double pow7(double x) { return std::pow(x, 7.0); }

// h' in degrees, [0, 360); 0 where a' = b' = 0 (Sharma et al., eq. 7).
double hueAngle(double b, double aPrime) {
  if (b == 0.0 && aPrime == 0.0) return 0.0;
  const double h = degrees(std::atan2(b, aPrime));
  return h < 0.0 ? h + 360.0 : h;
}

}  // namespace

double ciede2000(const Lab& c1, const Lab& c2) {
  // Step 1: C', h'.
  const double cStar1 = std::hypot(c1.a, c1.b);
  const double cStar2 = std::hypot(c2.a, c2.b);
  const double cBar = 0.5 * (cStar1 + cStar2);
  const double g = 0.5 * (1.0 - std::sqrt(pow7(cBar) / (pow7(cBar) + pow7(25.0))));
  const double a1 = (1.0 + g) * c1.a;
  const double a2 = (1.0 + g) * c2.a;
  const double cp1 = std::hypot(a1, c1.b);
  const double cp2 = std::hypot(a2, c2.b);
  const double hp1 = hueAngle(c1.b, a1);
  const double hp2 = hueAngle(c2.b, a2);

  // Step 2: dL', dC', dH'.
  const double dL = c2.L - c1.L;
  const double dC = cp2 - cp1;
  double dh = 0.0;
  if (cp1 * cp2 != 0.0) {
    dh = hp2 - hp1;
    if (dh > 180.0)
      dh -= 360.0;
    else if (dh < -180.0)
      dh += 360.0;
  }
  const double dH = 2.0 * std::sqrt(cp1 * cp2) * std::sin(radians(dh / 2.0));

  // Step 3: the weighting functions.
  const double lBar = 0.5 * (c1.L + c2.L);
  const double cpBar = 0.5 * (cp1 + cp2);
  double hBar = hp1 + hp2;
  if (cp1 * cp2 != 0.0) {
    if (std::abs(hp1 - hp2) <= 180.0)
      hBar = 0.5 * (hp1 + hp2);
    else if (hp1 + hp2 < 360.0)
      hBar = 0.5 * (hp1 + hp2 + 360.0);
    else
      hBar = 0.5 * (hp1 + hp2 - 360.0);
  }
  const double t =
      1.0 - 0.17 * std::cos(radians(hBar - 30.0)) + 0.24 * std::cos(radians(2.0 * hBar)) +
      0.32 * std::cos(radians(3.0 * hBar + 6.0)) - 0.20 * std::cos(radians(4.0 * hBar - 63.0));
  const double dTheta = 30.0 * std::exp(-std::pow((hBar - 275.0) / 25.0, 2.0));
  const double rC = 2.0 * std::sqrt(pow7(cpBar) / (pow7(cpBar) + pow7(25.0)));
  const double lShift = (lBar - 50.0) * (lBar - 50.0);
  const double sL = 1.0 + 0.015 * lShift / std::sqrt(20.0 + lShift);
  const double sC = 1.0 + 0.045 * cpBar;
  const double sH = 1.0 + 0.015 * cpBar * t;
  const double rT = -std::sin(radians(2.0 * dTheta)) * rC;

  const double l = dL / sL, c = dC / sC, h = dH / sH;
  return std::sqrt(l * l + c * c + h * h + rT * c * h);
}

Lab linearSrgbToLab(double r, double g, double b) {
  r = std::clamp(r, 0.0, 1.0);
  g = std::clamp(g, 0.0, 1.0);
  b = std::clamp(b, 0.0, 1.0);
  // IEC 61966-2-1, linear RGB to XYZ (D65).
  const double x = 0.4124 * r + 0.3576 * g + 0.1805 * b;
  const double y = 0.2126 * r + 0.7152 * g + 0.0722 * b;
  const double z = 0.0193 * r + 0.1192 * g + 0.9505 * b;
  // The white of the same matrix (r = g = b = 1).
  constexpr double xn = 0.9505, yn = 1.0, zn = 1.089;
  auto f = [](double ratio) {
    constexpr double delta = 6.0 / 29.0;
    return ratio > delta * delta * delta ? std::cbrt(ratio)
                                         : ratio / (3.0 * delta * delta) + 4.0 / 29.0;
  };
  const double fx = f(x / xn), fy = f(y / yn), fz = f(z / zn);
  return {116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)};
}

}  // namespace snell::bench
