#pragma once
// GLSL vectors and square matrices over a number type T, with the
// constructors, swizzles and operators the listings use. Matrices are
// column-major, as GLSL stores them: m[c] is column c.
#include <array>
#include <cstddef>
#include <span>
#include <utility>

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

  // Component k is f(k), called for k = 0, 1, ... in order and built in
  // place: an Interval is ~150 bytes, and building the vector first and
  // assigning each component over it copies every one of them.
  struct FromEach {};
  template <class F>
  vec(FromEach, F&& f) : c(build(f, std::make_index_sequence<N>{})) {}

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

 private:
  // Braced initialisation evaluates f(0), f(1), ... left to right.
  template <class F, std::size_t... K>
  static std::array<T, N> build(F& f, std::index_sequence<K...>) {
    return {f(static_cast<int>(K))...};
  }
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
  return vec<T, N>(typename vec<T, N>::FromEach{}, [&](int) { return value; });
}

template <class T, int N, class Op>
vec<T, N> componentwise(const vec<T, N>& a, const vec<T, N>& b, Op op) {
  return vec<T, N>(typename vec<T, N>::FromEach{}, [&](int k) { return op(a[k], b[k]); });
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
  return vec<T, N>(typename vec<T, N>::FromEach{}, [&](int k) { return -a[k]; });
}
template <class T, int N>
vec<T, N> operator*(const T& s, const vec<T, N>& v) {
  return vec<T, N>(typename vec<T, N>::FromEach{}, [&](int k) { return s * v[k]; });
}
template <class T, int N>
vec<T, N> operator*(const vec<T, N>& v, const T& s) {
  return vec<T, N>(typename vec<T, N>::FromEach{}, [&](int k) { return v[k] * s; });
}
template <class T, int N>
vec<T, N> operator/(const vec<T, N>& v, const T& s) {
  return vec<T, N>(typename vec<T, N>::FromEach{}, [&](int k) { return v[k] / s; });
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
