#pragma once
// Checks shared by the physics reference's entry points: a refractive index
// is a finite number above 0, and a bad one is the caller's to fix.
#include <fmt/format.h>

#include <cmath>

#include "core/errors.h"

namespace snell::physics {

inline void checkIndex(double n, const char* name) {
  if (!(std::isfinite(n) && n > 0.0))
    throw UsageError(
        fmt::format("{} must be a refractive index, a finite number above 0 (got {})", name, n));
}

}  // namespace snell::physics
