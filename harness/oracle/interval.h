#pragma once
// Interval: the set of fp32 results that the GLSL 4.60 (section 4.7.1) and
// Vulkan (SPIR-V precision appendix) rules allow for an expression, as a
// closed range [lo, hi] whose bounds are floats. Each operation maps the
// allowed inputs to every result any conforming implementation may return,
// so an interval computed along a listing's expression is the gate that a
// read-back value is checked against.
//
// This header has the number type and the correctly rounded operations;
// interval_builtins.h has the built-in functions with looser bounds.
#include "oracle/fp32.h"

namespace snell {

struct Interval {
  double lo = 0.0;
  double hi = 0.0;
  // The spec does not constrain the value (undefined or unspecified: pow of
  // a negative base, a divisor that may be 0, NaN, ...). Every result is
  // allowed, NaN included; lo and hi are then -inf and +inf. Any operation on
  // an undefined operand is undefined.
  bool undefined = false;

  constexpr Interval() = default;
  constexpr Interval(double low, double high) : lo(low), hi(high) {}

  // A float as a shader sees it: a literal, an input or a uniform. A
  // denormal may be flushed to 0 on the way in.
  static Interval point(float value);
  static Interval unconstrained();
};

// The result of comparing intervals: an implementation's branch is known
// only when every allowed value agrees.
enum class Truth { False, True, Unknown };

// + - * are correctly rounded, and a*b+c may be fused: the exact result
// range, widened to the floats on either side of it (the rounding mode is not
// fixed), admitting 0 where the range reaches the denormals (flush to zero).
// Fusion needs no extra rule: rounding each step outward already contains the
// singly rounded fused result.
Interval operator+(const Interval& a, const Interval& b);
Interval operator-(const Interval& a, const Interval& b);
Interval operator*(const Interval& a, const Interval& b);
Interval operator-(const Interval& a);  // exact
// 2.5 ULP for |b| in [2^-126, 2^126]; outside that the spec gives no bound
// and a divisor that may be 0 gives an unspecified value: both unconstrained.
Interval operator/(const Interval& a, const Interval& b);

Truth operator<(const Interval& a, const Interval& b);

// Whether an implementation may return `value`.
bool contains(const Interval& range, float value);
// Whether an exact (real) value lies in the range; for checking the oracle.
bool contains(const Interval& range, double value);
double width(const Interval& range);

// The smallest interval holding both: what a branch gives when the
// condition is unknown.
Interval hull(const Interval& a, const Interval& b);

// The floats within `ulps` fp32 ULPs (of the exact value) of some value in
// [exactLo, exactHi]. The exact bounds must already account for any error
// of their own computation.
Interval withinUlps(double exactLo, double exactHi, double ulps);
// The floats within an absolute distance of [exactLo, exactHi].
Interval withinDistance(double exactLo, double exactHi, double distance);

}  // namespace snell
