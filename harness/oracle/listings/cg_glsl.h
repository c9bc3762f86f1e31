#pragma once
// The GLSL pieces the Cg Tutorial ports use that oracle/glsl does not have:
// abs() over every number type and the mat3(mat4) constructor.
#include <algorithm>
#include <cmath>

#include "oracle/glsl/glsl.h"

namespace snell::listings {

// abs() over every number type: glsl::abs for double and float,
// snell::abs (oracle/interval_builtins.h) for Interval.
using glsl::abs;
using snell::abs;

// mat3(m): the upper-left 3x3, as Cg's (float3x3)m also takes it.
template <class T>
glsl::mat3<T> mat3Of(const glsl::mat4<T>& m) {
  glsl::mat3<T> r;
  for (int column = 0; column < 3; ++column) r[column] = glsl::vec3<T>(m[column]);
  return r;
}

}  // namespace snell::listings
