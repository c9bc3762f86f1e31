#pragma once
// Double-double numbers: a value held as the unevaluated sum hi + lo of two
// doubles (about 106 bits), for the few places where the oracle's double
// reference would otherwise lose digits to cancellation: dot products of
// nearly perpendicular vectors, and refract()'s k = 1 - eta^2 (1 - d^2) at
// grazing incidence with eta near 1, where k is about d^2 and 1 - d^2
// rounded in double keeps only 1e-16 / d^2 of it.
#include <cmath>

namespace snell::glsl {

struct DoubleDouble {
  double hi = 0.0;
  double lo = 0.0;
};

// Error-free transformations (Knuth's two-sum, an fma for the product).
inline DoubleDouble twoSum(double a, double b) {
  const double s = a + b;
  const double bVirtual = s - a;
  return {s, (a - (s - bVirtual)) + (b - bVirtual)};
}
inline DoubleDouble twoProduct(double a, double b) {
  const double p = a * b;
  return {p, std::fma(a, b, -p)};
}
inline DoubleDouble normalized(double hi, double lo) {
  const double s = hi + lo;
  return {s, lo - (s - hi)};
}

inline DoubleDouble operator+(DoubleDouble a, DoubleDouble b) {
  const DoubleDouble s = twoSum(a.hi, b.hi);
  const DoubleDouble t = twoSum(a.lo, b.lo);
  const DoubleDouble u = normalized(s.hi, s.lo + t.hi);
  return normalized(u.hi, u.lo + t.lo);
}
inline DoubleDouble operator-(DoubleDouble a) { return {-a.hi, -a.lo}; }
inline DoubleDouble operator-(DoubleDouble a, DoubleDouble b) { return a + (-b); }
inline DoubleDouble operator*(DoubleDouble a, DoubleDouble b) {
  const DoubleDouble p = twoProduct(a.hi, b.hi);
  return normalized(p.hi, p.lo + (a.hi * b.lo + a.lo * b.hi));
}

// The nearest double (where hi is not finite, hi itself).
inline double toDouble(DoubleDouble a) { return std::isfinite(a.hi) ? a.hi + a.lo : a.hi; }

}  // namespace snell::glsl
