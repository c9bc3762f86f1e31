#pragma once
// The GLSL pieces the Cg Tutorial ports use that oracle/glsl does not have:
// abs() over every number type and the mat3(mat4) constructor.
#include <algorithm>
#include <cmath>

#include "oracle/glsl/glsl.h"

namespace snell::listings {

inline double abs(double x) { return std::fabs(x); }
inline float abs(float x) { return std::fabs(x); }

// abs is exact (a sign change), so the allowed results are exactly the
// magnitudes of the allowed arguments; a range across 0 reaches down to 0.
inline Interval abs(const Interval& x) {
  if (x.undefined || x.lo >= 0.0) return x;
  if (x.hi <= 0.0) return -x;
  return Interval(0.0, std::max(-x.lo, x.hi));
}

// mat3(m): the upper-left 3x3, as Cg's (float3x3)m also takes it.
template <class T>
glsl::mat3<T> mat3Of(const glsl::mat4<T>& m) {
  glsl::mat3<T> r;
  for (int column = 0; column < 3; ++column) r[column] = glsl::vec3<T>(m[column]);
  return r;
}

}  // namespace snell::listings
