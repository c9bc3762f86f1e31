#include "oracle/fp32.h"

#include <cmath>
#include <limits>

namespace snell {

double gapAbove(double x) {
  x = std::fabs(x);
  if (std::isnan(x)) return x;
  if (x < kFp32MinNormal) return kFp32MinDenormal;
  if (x > kFp32Max) return 0x1p104;
  int exponent = 0;
  std::frexp(x, &exponent);  // x = m * 2^exponent, m in [0.5, 1)
  return std::ldexp(1.0, exponent - 1 - 23);
}

double ulp(double x) {
  const double gap = gapAbove(x);
  x = std::fabs(x);
  int exponent = 0;
  const bool powerOfTwo = x > kFp32MinNormal && x <= kFp32Max && std::frexp(x, &exponent) == 0.5;
  return powerOfTwo ? gap * 0.5 : gap;
}

double floatAtOrBelow(double x) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  if (std::isnan(x) || std::isinf(x)) return x;
  // Outside the float range the cast is not defined by the language.
  if (x > kFp32Max) return kFp32Max;
  if (x < -kFp32Max) return -kInf;
  // The cast rounds to nearest: at most one float away from the answer.
  const float nearest = static_cast<float>(x);
  if (static_cast<double>(nearest) <= x) return nearest;
  return std::nextafter(nearest, -std::numeric_limits<float>::infinity());
}

double floatAtOrAbove(double x) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  if (std::isnan(x) || std::isinf(x)) return x;
  if (x > kFp32Max) return kInf;
  if (x < -kFp32Max) return -kFp32Max;
  const float nearest = static_cast<float>(x);
  if (static_cast<double>(nearest) >= x) return nearest;
  return std::nextafter(nearest, std::numeric_limits<float>::infinity());
}

bool isFloat(double x) { return std::isnan(x) || floatAtOrBelow(x) == x; }

float nearestFloat(double x) { return static_cast<float>(x); }

}  // namespace snell
