#pragma once
// The GLSL geometric and common built-ins the listings call, each written as
// its defining formula (GLSL 4.60 section 8), so that with Interval the
// formula's own operations carry the "inherited" precision.
#include "oracle/glsl/branch.h"
#include "oracle/glsl/vector.h"

namespace snell::glsl {

template <class T, int Size>
T dot(const vec<T, Size>& x, const vec<T, Size>& y) {
  return sumOfProducts(x.components(), y.components());
}

template <class T, int Size>
T length(const vec<T, Size>& x) {
  return sqrt(dot(x, x));
}

template <class T, int Size>
vec<T, Size> normalize(const vec<T, Size>& x) {
  return x / length(x);
}

template <class T, int Size>
vec<T, Size> reflect(const vec<T, Size>& I, const vec<T, Size>& N) {
  return I - lit<T>(2.0) * dot(N, I) * N;
}

// k = 1.0 - eta * eta * (1.0 - dot(N, I) * dot(N, I));
// if (k < 0.0) return genType(0.0);
// else return eta * I - (eta * dot(N, I) + sqrt(k)) * N;
// sqrt takes max(k, 0): where k may be either side of 0 the formula branch
// only ever sees the k >= 0 part.
template <class T, int Size>
vec<T, Size> refract(const vec<T, Size>& I, const vec<T, Size>& N, const T& eta) {
  const T d = dot(N, I);
  const T k = lit<T>(1.0) - eta * eta * (lit<T>(1.0) - d * d);
  return branch(
      k < lit<T>(0.0), [&] { return splat<T, Size>(lit<T>(0.0)); },
      [&] { return eta * I - (eta * d + sqrt(max(k, lit<T>(0.0)))) * N; });
}

// x * (1 - a) + y * a
template <Number T>
T mix(const T& x, const T& y, const T& a) {
  return x * (lit<T>(1.0) - a) + y * a;
}

template <class T, int Size>
vec<T, Size> mix(const vec<T, Size>& x, const vec<T, Size>& y, const T& a) {
  return x * (lit<T>(1.0) - a) + y * a;
}

}  // namespace snell::glsl
