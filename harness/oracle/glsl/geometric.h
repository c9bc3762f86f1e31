#pragma once
// The GLSL geometric and common built-ins the listings call, each written as
// its defining formula (GLSL 4.60 section 8), so that with Interval the
// formula's own operations carry the "inherited" precision.
#include "oracle/glsl/branch.h"
#include "oracle/glsl/vector.h"

namespace snell::glsl {

// Vulkan states an inherited built-in's bound as [x - E, x + E] about the
// exact result x (oracle/precision_rules.h): under its rules the allowed
// set of an Interval result is made symmetric about its ideal value.
inline Interval inherited(const Interval& value) {
  return currentPrecisionRules() == PrecisionRules::Vulkan ? symmetricAboutIdeal(value) : value;
}
template <class T>
T inherited(const T& value) {
  return value;
}
template <class T, int Size>
vec<T, Size> inherited(const vec<T, Size>& v) {
  return vec<T, Size>(typename vec<T, Size>::FromEach{}, [&](int k) { return inherited(v[k]); });
}

template <class T, int Size>
T dot(const vec<T, Size>& x, const vec<T, Size>& y) {
  return inherited(sumOfProducts(x.components(), y.components()));
}

template <class T, int Size>
T length(const vec<T, Size>& x) {
  return inherited(sqrt(dot(x, x)));
}

// A number type that models one implementation's choices (the tests'
// adversarial machine) says which of several legal formulas a call uses.
template <class T>
concept ChoosesFormula = requires {
  T::chooseFormula(2);
};

// GLSL: x / length(x). Vulkan's table gives x * inversesqrt(dot(x, x)),
// and a SPIR-V module compiled from GLSL may equally carry GLSL's formula,
// which is no less accurate: under Vulkan both are allowed.
template <class T, int Size>
vec<T, Size> normalize(const vec<T, Size>& x) {
  if (currentPrecisionRules() != PrecisionRules::Vulkan) return x / length(x);
  if constexpr (std::same_as<T, Interval>) {
    const vec<T, Size> product = x * inversesqrt(dot(x, x));
    const vec<T, Size> quotient = x / length(x);
    vec<T, Size> r;
    for (int k = 0; k < Size; ++k) r[k] = withAlternative(product[k], quotient[k]);
    return inherited(r);
  } else if constexpr (ChoosesFormula<T>) {
    if (T::chooseFormula(2) == 0) return x / length(x);
    return x * inversesqrt(dot(x, x));
  } else {
    return x * inversesqrt(dot(x, x));
  }
}

template <class T, int Size>
vec<T, Size> reflect(const vec<T, Size>& I, const vec<T, Size>& N) {
  return inherited(I - lit<T>(2.0) * dot(N, I) * N);
}

// refract()'s k = 1.0 - eta * eta * (1.0 - d * d).
template <class T>
T refractK(const T& eta, const T& d) {
  return lit<T>(1.0) - eta * eta * (lit<T>(1.0) - d * d);
}
// The reference value in double-double: near grazing with eta near 1, k is
// about d^2 and would cancel in double.
inline double refractK(const double& eta, const double& d) {
  const DoubleDouble one{1.0, 0.0};
  return toDouble(one - twoProduct(eta, eta) * (one - twoProduct(d, d)));
}

// k = 1.0 - eta * eta * (1.0 - dot(N, I) * dot(N, I));
// if (k < 0.0) return genType(0.0);
// else return eta * I - (eta * dot(N, I) + sqrt(k)) * N;
// sqrt takes max(k, 0): where k may be either side of 0 the formula branch
// only ever sees the k >= 0 part.
template <class T, int Size>
vec<T, Size> refract(const vec<T, Size>& I, const vec<T, Size>& N, const T& eta) {
  const T d = dot(N, I);
  const T k = refractK(eta, d);
  return branch(
      k < lit<T>(0.0), [&] { return splat<T, Size>(lit<T>(0.0)); },
      [&] { return inherited(eta * I - (eta * d + sqrt(max(k, lit<T>(0.0)))) * N); });
}

// x * (1 - a) + y * a. Compilers also lower it as x + (y - x) * a (Mesa's
// flrp becomes an fma of that form on both APIs), a distributed form that
// the GLSL rules alone would not reach: like dEQP, the GLSL rules take
// both (Vulkan's distributivity already covers the second).
template <Number T>
T mix(const T& x, const T& y, const T& a) {
  const T written = x * (lit<T>(1.0) - a) + y * a;
  if constexpr (std::same_as<T, Interval>) {
    if (currentPrecisionRules() == PrecisionRules::Glsl)
      return withAlternative(written, x + (y - x) * a);
    return inherited(written);
  } else if constexpr (ChoosesFormula<T>) {
    return T::chooseFormula(2) == 0 ? written : x + (y - x) * a;
  } else {
    return written;
  }
}

template <class T, int Size>
vec<T, Size> mix(const vec<T, Size>& x, const vec<T, Size>& y, const T& a) {
  vec<T, Size> r;
  for (int k = 0; k < Size; ++k) r[k] = mix(x[k], y[k], a);
  return r;
}

}  // namespace snell::glsl
