#pragma once
// The dEQP-style interval: plain interval arithmetic in which each
// operation's exact result range is rounded outward by that operation's
// allowance (glsBuiltinPrecisionTests' way), and where an expression may be
// evaluated in several ways (groupings, fused multiply-adds, either side of
// a branch) the union of the ways. It is the yardstick that snell's oracle
// is measured against, kept deliberately simple; it is not the oracle.
//
// Allowances (GLSL 4.60 section 4.7.1, Vulkan SPIR-V precision appendix,
// fp32): + - * and fma correctly rounded in either direction, results below
// the smallest normal may be flushed to 0; / 2.5 ULP for |divisor| in
// [2^-126, 2^126]; inversesqrt 2 ULP; sqrt inherited from 1 / inversesqrt;
// exp2 and exp 3 + 2|x| ULP; log2 3 ULP outside [0.5, 2], absolute 2^-21
// inside; pow inherited from exp2(y * log2(x)). Anything else is
// undefined (every value allowed).
#include <span>

#include "oracle/glsl/glsl.h"
#include "oracle/interval.h"
#include "widths/chain.h"

namespace snell::widths {

struct DeqpValue {
  double lo = 0.0;
  double hi = 0.0;
  bool undefined = false;
};

struct DeqpArith {
  using Value = DeqpValue;
  static Value point(float x) { return {x, x, false}; }
  static Value neg(const Value& a) { return {-a.hi, -a.lo, a.undefined}; }
  static Value add(const Value& a, const Value& b);
  static Value mul(const Value& a, const Value& b);
  static Value fma(const Value& a, const Value& b, const Value& c);
  static Value choose(std::span<const Value> ways);  // the union
  static Value div(const Value& a, const Value& b);
  static Value inversesqrt(const Value& x);
  static Value sqrt(const Value& x);
  static Value exp2(const Value& x);
  static Value exp(const Value& x);
  static Value log2(const Value& x);
  static Value pow(const Value& x, const Value& y);
  static Value max(const Value& a, const Value& b);
  static Value min(const Value& a, const Value& b);
  static Value abs(const Value& x);
  static Truth less(const Value& a, const Value& b);
  static bool isUndefined(const Value& x) { return x.undefined; }
};

using Deqp = Chain<DeqpArith>;

// The exact range [lo, hi] widened to every float a correctly rounded
// result may be, flushed denormals included.
DeqpValue roundedOutward(double lo, double hi);

}  // namespace snell::widths
