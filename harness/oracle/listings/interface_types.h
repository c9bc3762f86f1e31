#pragma once
// How a listing's interface variables (glsl::vec, glsl::mat or a scalar, over
// any number type) map to the harness's flat float values: their GLSL type,
// and their components in GLSL's order (matrices column by column).
#include "core/values.h"
#include "oracle/glsl/vector.h"

namespace snell::listings {

template <class X>
struct Shape;

template <glsl::Number T>
struct Shape<T> {
  static constexpr ValueType type = ValueType::Float;
};
template <class T>
struct Shape<glsl::vec<T, 2>> {
  static constexpr ValueType type = ValueType::Vec2;
};
template <class T>
struct Shape<glsl::vec<T, 3>> {
  static constexpr ValueType type = ValueType::Vec3;
};
template <class T>
struct Shape<glsl::vec<T, 4>> {
  static constexpr ValueType type = ValueType::Vec4;
};
template <class T>
struct Shape<glsl::mat<T, 3>> {
  static constexpr ValueType type = ValueType::Mat3;
};
template <class T>
struct Shape<glsl::mat<T, 4>> {
  static constexpr ValueType type = ValueType::Mat4;
};

template <class X>
constexpr ValueType glslTypeOf() {
  return Shape<X>::type;
}

// Visits every component in order; f gets a reference it may write through.
template <glsl::Number T, class F>
void forEachComponent(T& x, F&& f) {
  f(x);
}
template <class T, int N, class F>
void forEachComponent(glsl::vec<T, N>& v, F&& f) {
  for (int k = 0; k < N; ++k) f(v[k]);
}
template <class T, int N, class F>
void forEachComponent(glsl::mat<T, N>& m, F&& f) {
  for (int column = 0; column < N; ++column) forEachComponent(m[column], f);
}

}  // namespace snell::listings
