#pragma once
// The scalar side of the GLSL built-ins for the plain number types: double
// gives exact math on the fp32 inputs (as near as double gets), float what a
// strict fp32 machine computes. Interval has the same names in
// interval_builtins.h; the templates in this folder call them unqualified
// and get whichever fits T.
#include <cmath>
#include <concepts>
#include <cstddef>
#include <span>
#include <type_traits>

#include "oracle/glsl/double_double.h"
#include "oracle/interval.h"
#include "oracle/interval_builtins.h"
#include "oracle/precision_rules.h"

namespace snell::glsl {

// The number types a listing is instantiated for: double (exact value),
// float (a strict fp32 machine), Interval (what the spec allows). Tests add
// their own (an adversarial fp32 machine) by specialising IsNumber.
template <class T>
struct IsNumber : std::false_type {};
template <>
struct IsNumber<double> : std::true_type {};
template <>
struct IsNumber<float> : std::true_type {};
template <>
struct IsNumber<Interval> : std::true_type {};

template <class T>
concept Number = IsNumber<T>::value;

// A GLSL float literal or `const float`: the nearest float, in T. A number
// type that models constant folding (Interval, test machines) gets the
// decimal as written through T::literal.
template <Number T>
T lit(double value) {
  if constexpr (requires { T::literal(value); }) {
    return T::literal(value);
  } else {
    return static_cast<T>(nearestFloat(value));
  }
}

// An fp32 input value (uniform, attribute) in T.
template <Number T>
T fromFloat(float value) {
  if constexpr (std::same_as<T, Interval>) {
    return Interval::point(value);
  } else {
    return static_cast<T>(value);
  }
}

inline double sqrt(double x) { return std::sqrt(x); }
inline float sqrt(float x) { return std::sqrt(x); }
inline double inversesqrt(double x) { return 1.0 / std::sqrt(x); }
inline float inversesqrt(float x) { return 1.0f / std::sqrt(x); }
inline double exp2(double x) { return std::exp2(x); }
inline float exp2(float x) { return std::exp2(x); }
inline double exp(double x) { return std::exp(x); }
inline float exp(float x) { return std::exp(x); }
inline double log2(double x) { return std::log2(x); }
inline float log2(float x) { return std::log2(x); }
inline double pow(double x, double y) { return std::pow(x, y); }
inline float pow(float x, float y) { return std::pow(x, y); }
inline double max(double a, double b) { return b > a ? b : a; }
inline float max(float a, float b) { return b > a ? b : a; }
inline double min(double a, double b) { return b < a ? b : a; }
inline float min(float a, float b) { return b < a ? b : a; }
inline double abs(double x) { return std::fabs(x); }
inline float abs(float x) { return std::fabs(x); }

// dot() and matrix * vector in one fixed order: the order a strict machine
// uses. (The Interval overload covers every order.)
template <std::floating_point T>
T sumOfProducts(std::span<const T> a, std::span<const T> b) {
  T sum = a[0] * b[0];
  for (std::size_t i = 1; i < a.size(); ++i) sum = sum + a[i] * b[i];
  return sum;
}
// The reference value: exact products summed in double-double, so that a
// dot product of nearly perpendicular vectors keeps its digits.
inline double sumOfProducts(std::span<const double> a, std::span<const double> b) {
  DoubleDouble sum;
  for (std::size_t i = 0; i < a.size(); ++i) sum = sum + twoProduct(a[i], b[i]);
  return toDouble(sum);
}

// Whether a value is one the spec leaves open.
inline bool isUndefined(double x) { return std::isnan(x); }
inline bool isUndefined(float x) { return std::isnan(x); }
inline bool isUndefined(const Interval& x) { return x.undefined; }

}  // namespace snell::glsl
