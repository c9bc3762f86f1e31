#pragma once
// GLSL vectors and square matrices over a number type T, with the
// constructors, swizzles and operators the listings use. Matrices are
// column-major, as GLSL stores them: m[c] is column c.
#include <array>
#include <span>

#include "oracle/glsl/scalar.h"

namespace snell::glsl {

template <class T, int N>
struct vec {
  static_assert(N >= 1 && N <= 4);
  std::array<T, N> c{};

  vec() = default;
  template <class... S>
  requires(sizeof...(S) == N && (std::same_as<S, T> && ...)) vec(const S&... components)
      : c{components...} {}
  // vec4(v.xyz, 1.0)
  template <int M>
  requires(M + 1 == N) vec(const vec<T, M>& head, const T& last) {
    for (int k = 0; k < M; ++k) c[k] = head[k];
    c[M] = last;
  }
  // vec3(v4): GLSL keeps the leading components.
  template <int M>
  requires(M > N) explicit vec(const vec<T, M>& wider) {
    for (int k = 0; k < N; ++k) c[k] = wider[k];
  }

  T& operator[](int k) { return c[k]; }
  const T& operator[](int k) const { return c[k]; }
  std::span<const T> components() const { return c; }

  const T& x() const { return c[0]; }
  const T& y() const requires(N >= 2) { return c[1]; }
  const T& z() const requires(N >= 3) { return c[2]; }
  const T& w() const requires(N >= 4) { return c[3]; }
  vec<T, 3> xyz() const requires(N >= 3) { return vec<T, 3>(c[0], c[1], c[2]); }

  // The colour names of the same components: a fragment part writes
  // `refractColor.r = ...`. (cppcheck 2.10 ignores the requires clauses and
  // reports c[1], c[2] out of bounds for vec<T, 1>; they cannot be called there.)
  T& r() { return c[0]; }
  // cppcheck-suppress containerOutOfBounds
  T& g() requires(N >= 2) { return c[1]; }
  // cppcheck-suppress containerOutOfBounds
  T& b() requires(N >= 3) { return c[2]; }
  const T& r() const { return c[0]; }
  const T& g() const requires(N >= 2) { return c[1]; }
  const T& b() const requires(N >= 3) { return c[2]; }
};

template <class T>
using vec2 = vec<T, 2>;
template <class T>
using vec3 = vec<T, 3>;
template <class T>
using vec4 = vec<T, 4>;

template <class T, int N>
struct mat {
  std::array<vec<T, N>, N> columns{};
  vec<T, N>& operator[](int column) { return columns[column]; }
  const vec<T, N>& operator[](int column) const { return columns[column]; }
};

template <class T>
using mat3 = mat<T, 3>;
template <class T>
using mat4 = mat<T, 4>;

// A vector with every component `value`: GLSL's vec3(0.0).
template <class T, int N>
vec<T, N> splat(const T& value) {
  vec<T, N> r;
  for (int k = 0; k < N; ++k) r[k] = value;
  return r;
}

template <class T, int N, class Op>
vec<T, N> componentwise(const vec<T, N>& a, const vec<T, N>& b, Op op) {
  vec<T, N> r;
  for (int k = 0; k < N; ++k) r[k] = op(a[k], b[k]);
  return r;
}

template <class T, int N>
vec<T, N> operator+(const vec<T, N>& a, const vec<T, N>& b) {
  return componentwise(a, b, [](const T& x, const T& y) { return x + y; });
}
template <class T, int N>
vec<T, N> operator-(const vec<T, N>& a, const vec<T, N>& b) {
  return componentwise(a, b, [](const T& x, const T& y) { return x - y; });
}
template <class T, int N>
vec<T, N> operator-(const vec<T, N>& a) {
  vec<T, N> r;
  for (int k = 0; k < N; ++k) r[k] = -a[k];
  return r;
}
template <class T, int N>
vec<T, N> operator*(const T& s, const vec<T, N>& v) {
  vec<T, N> r;
  for (int k = 0; k < N; ++k) r[k] = s * v[k];
  return r;
}
template <class T, int N>
vec<T, N> operator*(const vec<T, N>& v, const T& s) {
  vec<T, N> r;
  for (int k = 0; k < N; ++k) r[k] = v[k] * s;
  return r;
}
template <class T, int N>
vec<T, N> operator/(const vec<T, N>& v, const T& s) {
  vec<T, N> r;
  for (int k = 0; k < N; ++k) r[k] = v[k] / s;
  return r;
}

// Each row is a sum of products, so it gets dot()'s freedom of order.
template <class T, int N>
vec<T, N> operator*(const mat<T, N>& m, const vec<T, N>& v) {
  vec<T, N> r;
  for (int row = 0; row < N; ++row) {
    std::array<T, N> rowValues;
    for (int column = 0; column < N; ++column) rowValues[column] = m[column][row];
    r[row] = sumOfProducts(std::span<const T>(rowValues), v.components());
  }
  return r;
}

// The union of two vectors' allowed values, component by component.
template <int N>
vec<Interval, N> hull(const vec<Interval, N>& a, const vec<Interval, N>& b) {
  return componentwise(a, b,
                       [](const Interval& x, const Interval& y) { return snell::hull(x, y); });
}

}  // namespace snell::glsl
