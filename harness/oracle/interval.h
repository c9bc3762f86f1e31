#pragma once
// Interval: the set of fp32 results that the GLSL 4.60 (section 4.7.1) and
// Vulkan (SPIR-V precision appendix) rules allow for an expression, as a
// closed range [lo, hi] whose bounds are floats. Each operation maps the
// allowed inputs to every result any conforming implementation may return,
// so an interval computed along a listing's expression is the gate that a
// read-back value is checked against.
//
// An implementation need not evaluate the expression as written: without
// `precise` it may regroup sums and products, fuse a*b+c, and (Vulkan only)
// distribute products over sums (oracle/precision_rules.h). No single
// evaluation order is "the" one, so an Interval also carries a running
// error analysis that holds for every order at once:
// - ideal: the range of the exact value of the expression as written,
//   evaluated in real arithmetic from the shader's own fp32 inputs;
// - err: a bound on |computed - ideal| that holds at every input point for
//   every legal evaluation (every grouping, fusion and rounding choice);
// - region: while a sum or product is still open (its consumer may regroup
//   it with its own operands), the few numbers that bound the rounding
//   error of every regrouping of the whole region (oracle/interval_region.h).
// [lo, hi] follows from those: the floats within err of the ideal range,
// intersected with the plain interval of the written order where only one
// order exists.
//
// This header has the number type and + - * /; interval_builtins.h has the
// built-in functions.
#include "oracle/fp32.h"
#include "oracle/interval_region.h"

namespace snell {

struct Interval {
  double lo = 0.0;
  double hi = 0.0;
  // The spec does not constrain the value (undefined or unspecified: pow of
  // a negative base, a divisor that may be 0, NaN, a possible overflow
  // inside a regrouped expression, ...). Every result is allowed, NaN
  // included; lo and hi are then -inf and +inf. Any operation on an
  // undefined operand is undefined.
  bool undefined = false;

  // The error analysis above. For an input, literal or uniform: ideal is
  // the float itself and err is 0.
  double idealLo = 0.0;
  double idealHi = 0.0;
  double err = 0.0;
  IntervalRegion region;

  // A constant expression (literals and `const` values only) may be folded
  // by the compiler in any precision at least fp32's (GLSL 4.60 section
  // 4.3.3), from the decimal literals as written: glslang folds in double
  // from the unrounded literal. `folded` is that double evaluation.
  bool constant = false;
  double folded = 0.0;

  constexpr Interval() = default;
  // Any float in [low, high], each taken as exact (an input that may be
  // any of those floats).
  Interval(double low, double high);

  // A float as a shader sees it: an input or a uniform. A denormal may be
  // flushed to 0 on the way in.
  static Interval point(float value);
  // A literal or `const float` as printed: the nearest float at run time,
  // `decimal` itself when the compiler folds a constant expression.
  static Interval literal(double decimal);
  static Interval unconstrained();
};

// The result of comparing intervals: an implementation's branch is known
// only when every allowed value agrees.
enum class Truth { False, True, Unknown };

// + - * are correctly rounded (either neighbouring float), a*b+c may be
// fused, and sums and products may be regrouped: see the header comment.
// Where a result may be below the smallest normal it may be flushed to 0.
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
// condition is unknown and alternatives are not kept apart.
Interval hull(const Interval& a, const Interval& b);

// The floats within `ulps` fp32 ULPs (of the exact value) of some value in
// [exactLo, exactHi]. The exact bounds must already account for any error
// of their own computation. ULP is Harrison's, as the Vulkan spec and dEQP
// define it: at an exact power of two it is the gap below.
Interval withinUlps(double exactLo, double exactHi, double ulps);
// The floats strictly within an absolute distance of [exactLo, exactHi]
// (the log2 rule is "absolute error < 2^-21").
Interval withinDistance(double exactLo, double exactHi, double distance);

// A value whose error analysis is known, as a leaf: the floats `lo`..`hi`
// it may take, its ideal range and its pointwise error bound. For the
// built-ins (interval_builtins.cpp). A non-finite err gives an
// unconstrained result.
Interval leafValue(double lo, double hi, double idealLo, double idealHi, double err);

// `value` as a closed leaf, for an operation that takes it whole (a
// built-in, a division, a factor of a sum under the GLSL rules). Under the
// GLSL rules, which need no pointwise error (no [x - E, x + E] rule), a leaf
// whose float set is narrower than its ideal range widened by its error is
// taken as "any float of its set, exactly".
Interval closedView(const Interval& value);

// `value` (an open region an implementation may regroup with its
// consumer) or, instead, `alternative` (another formula an implementation
// may use for the same built-in): the allowed set, ideal range and error
// bound of both, and value's region grown to hold the alternative as a
// leaf. Closing both into a hull would hide what a regrouping across the
// built-in can do (a partial product that overflows, or underflows and is
// then scaled up).
Interval withAlternative(const Interval& value, const Interval& alternative);

// A Vulkan built-in whose precision is inherited from a formula must return
// a value in [x - E, x + E] around the exact result x, E being the largest
// distance of any permitted value of any equivalent formula: the allowed
// set is made symmetric about the ideal value: every float, where a value
// of the formula may be past the float range.
Interval symmetricAboutIdeal(const Interval& value);

}  // namespace snell
