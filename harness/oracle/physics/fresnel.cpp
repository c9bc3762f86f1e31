#include "oracle/physics/fresnel.h"

#include <fmt/format.h>

#include <cmath>

#include "core/errors.h"
#include "oracle/glsl/double_double.h"
#include "oracle/physics/physics_input.h"

namespace snell::physics {
namespace {

using glsl::DoubleDouble;

void checkCosine(double cosIncident) {
  if (!(cosIncident >= 0.0 && cosIncident <= 1.0))
    throw UsageError(fmt::format(
        "cos_i must lie in [0, 1] (got {}): it is the cosine of the angle to the normal",
        cosIncident));
}

// a*c - b*d with one rounding error instead of three (an fma recovers the
// error of b*d), so that n1 cos_i - n2 cos_t keeps its digits when the two
// terms nearly cancel (indices close together, or near Brewster's angle).
double differenceOfProducts(double a, double c, double b, double d) {
  const double bd = b * d;
  const double bdError = std::fma(b, d, -bd);
  return std::fma(a, c, -bd) - bdError;
}

double squaredRatio(double numerator, double denominator) {
  const double r = numerator / denominator;
  return r * r;
}

double schlick(double cosine, double n1, double n2) {
  const double r0 = normalIncidenceReflectance(n1, n2);
  const double m = 1.0 - cosine;
  const double m2 = m * m;
  return r0 + (1.0 - r0) * (m2 * m2 * m);
}

}  // namespace

double transmittedCosineSquared(double cosIncident, double n1In, double n2In) {
  checkCosine(cosIncident);
  checkIndex(n1In, "n1");
  checkIndex(n2In, "n2");
  const auto [n1, n2] = scaledIndices(n1In, n2In);
  // (n2^2 - n1^2 + (n1 cos_i)^2) / n2^2, the numerator in double-double:
  // near the critical angle its terms cancel to almost nothing.
  const DoubleDouble n1cos = glsl::twoProduct(n1, cosIncident);
  const DoubleDouble numerator =
      glsl::twoProduct(n2, n2) - glsl::twoProduct(n1, n1) + n1cos * n1cos;
  return glsl::toDouble(numerator) / (n2 * n2);
}

FresnelReflectance fresnelExact(double cosIncident, double n1In, double n2In) {
  const double cos2t = transmittedCosineSquared(cosIncident, n1In, n2In);
  const auto [n1, n2] = scaledIndices(n1In, n2In);
  // Equal indices are no interface: nothing is reflected. (Computed, cos_i
  // below 1e-154 squares to 0 and the ratios below would give 1.)
  if (n1 == n2 && cosIncident > 0.0) return {0.0, 0.0, 0.0, false};
  if (cos2t < 0.0) return {1.0, 1.0, 1.0, true};
  const double ci = cosIncident;
  const double ct = std::sqrt(cos2t);
  FresnelReflectance r;
  r.s = squaredRatio(differenceOfProducts(n1, ci, n2, ct), n1 * ci + n2 * ct);
  r.p = squaredRatio(differenceOfProducts(n2, ci, n1, ct), n2 * ci + n1 * ct);
  // Grazing incidence with a grazing transmitted ray (n1 = n2, cos_i = 0)
  // gives 0/0: the limit is full reflection of a ray that skims the surface.
  if (std::isnan(r.s)) r.s = 1.0;
  if (std::isnan(r.p)) r.p = 1.0;
  r.unpolarised = 0.5 * (r.s + r.p);
  return r;
}

double normalIncidenceReflectance(double n1In, double n2In) {
  checkIndex(n1In, "n1");
  checkIndex(n2In, "n2");
  const auto [n1, n2] = scaledIndices(n1In, n2In);
  return squaredRatio(n1 - n2, n1 + n2);
}

double fresnelSchlick(double cosIncident, double n1, double n2) {
  checkCosine(cosIncident);
  return schlick(cosIncident, n1, n2);
}

double fresnelSchlickDenseSide(double cosIncident, double n1, double n2) {
  const double cos2t = transmittedCosineSquared(cosIncident, n1, n2);
  if (n1 <= n2) return schlick(cosIncident, n1, n2);
  if (cos2t < 0.0) return 1.0;
  return schlick(std::sqrt(cos2t), n1, n2);
}

}  // namespace snell::physics
