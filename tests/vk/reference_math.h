#pragma once
// reflect() and refract() in double, straight from their GLSL definitions,
// evaluated on the exact fp32 inputs the shader saw.
#include <array>
#include <cmath>

namespace snell::vktest {

using Vec3d = std::array<double, 3>;

inline double dot(const Vec3d& a, const Vec3d& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

inline Vec3d reflectRef(const Vec3d& i, const Vec3d& n) {
  const double d = dot(n, i);
  return {i[0] - 2 * d * n[0], i[1] - 2 * d * n[1], i[2] - 2 * d * n[2]};
}

// The k that decides refract()'s branch; results are ill-conditioned near k = 0.
inline double refractK(const Vec3d& i, const Vec3d& n, double eta) {
  const double d = dot(n, i);
  return 1 - eta * eta * (1 - d * d);
}

inline Vec3d refractRef(const Vec3d& i, const Vec3d& n, double eta) {
  const double d = dot(n, i);
  const double k = refractK(i, n, eta);
  if (k < 0) return {0, 0, 0};
  const double s = eta * d + std::sqrt(k);
  return {eta * i[0] - s * n[0], eta * i[1] - s * n[1], eta * i[2] - s * n[2]};
}

inline Vec3d normalizeRef(const Vec3d& v) {
  const double length = std::sqrt(dot(v, v));
  return {v[0] / length, v[1] / length, v[2] / length};
}

}  // namespace snell::vktest
