#include "oracle/physics/interface_angles.h"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "core/errors.h"
#include "oracle/physics/physics_input.h"

namespace snell::physics {
namespace {

constexpr double kDegreesPerRadian = 180.0 / std::numbers::pi;

}  // namespace

double criticalAngleDegrees(double n1, double n2) {
  checkIndex(n1, "n1");
  checkIndex(n2, "n2");
  if (!(n1 > n2))
    throw UsageError(fmt::format(
        "a critical angle needs n1 > n2, light leaving the denser medium (got n1 = {}, n2 = {})",
        n1, n2));
  // atan2(n2, sqrt(n1^2 - n2^2)) rather than asin(n2 / n1): asin is
  // ill-conditioned as n2 / n1 nears 1, and n1 - n2 is exact there.
  const auto [a, b] = scaledIndices(n1, n2);
  return std::atan2(b, std::sqrt((a - b) * (a + b))) * kDegreesPerRadian;
}

double brewsterAngleDegrees(double n1, double n2) {
  checkIndex(n1, "n1");
  checkIndex(n2, "n2");
  return std::atan2(n2, n1) * kDegreesPerRadian;
}

}  // namespace snell::physics
