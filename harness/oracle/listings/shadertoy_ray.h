#pragma once
// The eye ray of the Shadertoy lens and bubble post ("Reflections and
// Refractions"), shared by its three oracles: the post's four camera lines
// over the number type T, and the cross() they call, which oracle/glsl does
// not have.
#include "oracle/glsl/glsl.h"

namespace snell::listings {

// cross(x, y) as GLSL 4.60 section 8.5 defines it: a difference of
// products per component, each operation carrying its own rounding.
template <class T>
glsl::vec3<T> cross(const glsl::vec3<T>& x, const glsl::vec3<T>& y) {
  return glsl::vec3<T>(x[1] * y[2] - y[1] * x[2], x[2] * y[0] - y[2] * x[0],
                       x[0] * y[1] - y[0] * x[1]);
}

// The ray from the eye through the pixel at `uv`.
template <class T>
glsl::vec3<T> shadertoyRayDir(const glsl::vec2<T>& uv) {
  using namespace glsl;
  // vec3 up = vec3(0.0, 1.0, 0.0);
  const vec3<T> up(lit<T>(0.0), lit<T>(1.0), lit<T>(0.0));
  // vec3 forward = vec3(0.0, 0.0, 1.0);
  const vec3<T> forward(lit<T>(0.0), lit<T>(0.0), lit<T>(1.0));
  // vec3 right = cross(up, forward);
  const vec3<T> right = cross(up, forward);
  // vec3 ray_dir = normalize(up * uv.y + right *uv.x + forward);
  return normalize(up * uv.y() + right * uv.x() + forward);
}

}  // namespace snell::listings
