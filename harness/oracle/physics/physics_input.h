#pragma once
// Checks shared by the physics reference's entry points: a refractive index
// is a finite number above 0, and a bad one is the caller's to fix.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/errors.h"

namespace snell::physics {

inline void checkIndex(double n, const char* name) {
  if (!(std::isfinite(n) && n > 0.0))
    throw UsageError(
        fmt::format("{} must be a refractive index, a finite number above 0 (got {})", name, n));
}

// Reflectance and angles depend on the ratio of the indices only: both
// scaled by the same power of two (exact) so that the larger is in [1, 2),
// and neither their squares nor their sum overflows (n1 = 1e200 gave 0).
struct Indices {
  double n1;
  double n2;
};
inline Indices scaledIndices(double n1, double n2) {
  int exponent = 0;
  std::frexp(std::max(n1, n2), &exponent);
  return {std::ldexp(n1, 1 - exponent), std::ldexp(n2, 1 - exponent)};
}

}  // namespace snell::physics
