#include "oracle/physics/analytic_sphere.h"

#include <fmt/format.h>

#include <cmath>
#include <optional>

#include "core/errors.h"
#include "oracle/physics/fresnel.h"
#include "oracle/physics/physics_input.h"

namespace snell::physics {
namespace {

void checkInput(const Sphere& sphere, Vec3 direction, const SphereTraceLimits& limits) {
  checkIndex(sphere.index, "the sphere's index");
  checkIndex(sphere.outsideIndex, "the outside index");
  if (!(std::isfinite(sphere.radius) && sphere.radius > 0.0))
    throw UsageError(
        fmt::format("the sphere's radius must be finite and above 0 (got {})", sphere.radius));
  if (!(std::isfinite(length(direction)) && length(direction) > 0.0))
    throw UsageError("the ray's direction must be a finite, non-zero vector");
  if (limits.maxInternalHits < 0)
    throw UsageError(
        fmt::format("maxInternalHits must be 0 or more (got {})", limits.maxInternalHits));
}

// The first hit of origin + s direction (s > 0, direction unit) with the
// sphere from outside, if any.
std::optional<Vec3> entryPoint(const Sphere& sphere, Vec3 origin, Vec3 direction) {
  const Vec3 toOrigin = origin - sphere.centre;
  const double b = dot(toOrigin, direction);
  const double c = dot(toOrigin, toOrigin) - sphere.radius * sphere.radius;
  const double discriminant = b * b - c;
  if (discriminant <= 0.0) return std::nullopt;  // a tangent ray has nothing to refract into
  const double s = -b - std::sqrt(discriminant);
  if (s <= 0.0) return std::nullopt;
  return origin + s * direction;
}

// Back onto the surface: a point computed by stepping along chords drifts
// off by rounding error, and the normal is taken from it.
Vec3 onSurface(const Sphere& sphere, Vec3 point) {
  return sphere.centre + sphere.radius * normalize(point - sphere.centre);
}

Vec3 reflect(Vec3 direction, Vec3 normal) {
  return direction - 2.0 * dot(direction, normal) * normal;
}

// Snell's law with `facing` the unit normal on the incident side
// (dot(direction, facing) < 0), eta = n1 / n2, cosT from the same Fresnel
// evaluation so the split and the direction agree.
Vec3 refract(Vec3 direction, Vec3 facing, double eta, double cosT) {
  const double cosI = -dot(direction, facing);
  return normalize(eta * direction + (eta * cosI - cosT) * facing);
}

}  // namespace

SphereTrace traceSphere(const Sphere& sphere, Vec3 origin, Vec3 direction,
                        const SphereTraceLimits& limits) {
  checkInput(sphere, direction, limits);
  direction = normalize(direction);
  SphereTrace trace;
  const std::optional<Vec3> entry = entryPoint(sphere, origin, direction);
  if (!entry) {
    trace.exits.push_back({ExitKind::Missed, 0, origin, direction, 1.0});
    return trace;
  }

  const double nOut = sphere.outsideIndex, nIn = sphere.index;
  Vec3 point = onSurface(sphere, *entry);
  Vec3 normal = (1.0 / sphere.radius) * (point - sphere.centre);  // outward
  const double cosEntry = std::fmin(1.0, -dot(direction, normal));
  const FresnelReflectance atEntry = fresnelExact(cosEntry, nOut, nIn);
  trace.exits.push_back(
      {ExitKind::ReflectedAtEntry, 0, point, reflect(direction, normal), atEntry.unpolarised});
  if (atEntry.totalInternalReflection) return trace;

  double energy = atEntry.transmitted();
  direction = refract(direction, normal, nOut / nIn,
                      std::sqrt(transmittedCosineSquared(cosEntry, nOut, nIn)));
  int reflections = 0;
  while (trace.internalHits < limits.maxInternalHits && energy >= limits.stopBelowEnergy &&
         energy > 0.0) {
    // The chord from a surface point: |p + s d - c| = r gives s = -2 (p - c).d.
    point = onSurface(sphere, point + (-2.0 * dot(point - sphere.centre, direction)) * direction);
    normal = (1.0 / sphere.radius) * (point - sphere.centre);
    ++trace.internalHits;
    const double cosInside = std::fmin(1.0, std::fabs(dot(direction, normal)));
    const FresnelReflectance split = fresnelExact(cosInside, nIn, nOut);
    if (!split.totalInternalReflection) {
      const Vec3 out = refract(direction, -1.0 * normal, nIn / nOut,
                               std::sqrt(transmittedCosineSquared(cosInside, nIn, nOut)));
      trace.exits.push_back(
          {ExitKind::Refracted, reflections, point, out, energy * split.transmitted()});
    }
    energy *= split.unpolarised;
    direction = reflect(direction, normal);
    ++reflections;
  }
  trace.remaining = energy;
  return trace;
}

}  // namespace snell::physics
