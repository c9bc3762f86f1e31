#pragma once
// Unit vectors and incidence geometry for the oracle tests, computed in
// double and handed to the oracle as floats (the values a shader would get).
#include <array>
#include <cmath>
#include <random>

#include "oracle/glsl/glsl.h"

namespace snell::test {

using Dir = std::array<double, 3>;

inline double dotOf(const Dir& a, const Dir& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Dir crossOf(const Dir& a, const Dir& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline Dir scaled(const Dir& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
inline Dir plus(const Dir& a, const Dir& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
inline double lengthOf(const Dir& a) { return std::sqrt(dotOf(a, a)); }
inline Dir unit(const Dir& a) { return scaled(a, 1.0 / lengthOf(a)); }

inline Dir randomUnit(std::mt19937_64& rng) {
  std::normal_distribution<double> gauss;
  return unit({gauss(rng), gauss(rng), gauss(rng)});
}

// A unit vector perpendicular to `normal`, in a random direction.
inline Dir randomTangent(const Dir& normal, std::mt19937_64& rng) {
  const Dir r = randomUnit(rng);
  return unit(plus(r, scaled(normal, -dotOf(r, normal))));
}

// The incident direction (pointing at the surface) that makes angle theta
// with -normal, in the plane of normal and tangent.
inline Dir incidentAt(const Dir& normal, const Dir& tangent, double theta) {
  return plus(scaled(tangent, std::sin(theta)), scaled(normal, -std::cos(theta)));
}

inline Dir fromVec(const glsl::vec3<double>& v) { return {v[0], v[1], v[2]}; }

// The float a shader would be given for each component.
inline std::array<float, 3> toFloats(const Dir& a) {
  return {static_cast<float>(a[0]), static_cast<float>(a[1]), static_cast<float>(a[2])};
}

template <class T>
glsl::vec3<T> asVec(const std::array<float, 3>& a) {
  return glsl::vec3<T>(glsl::fromFloat<T>(a[0]), glsl::fromFloat<T>(a[1]),
                       glsl::fromFloat<T>(a[2]));
}

}  // namespace snell::test
