#pragma once
// The GLSL built-ins on Interval, each with the bound the precision rules
// give it (GLSL 4.60 section 4.7.1, Vulkan SPIR-V precision appendix). A
// built-in whose precision is "inherited" is its defining formula evaluated
// with the Interval operations.
#include <span>

#include "oracle/interval.h"

namespace snell {

// 2 ULP; undefined for x <= 0.
Interval inversesqrt(const Interval& x);
// Inherited from 1.0 / inversesqrt(x); sqrt(0) is 0 (the formula's limit),
// undefined for x < 0.
Interval sqrt(const Interval& x);
// 3 + 2|x| ULP.
Interval exp2(const Interval& x);
// 3 + 2|x| ULP.
Interval exp(const Interval& x);
// 3 ULP outside [0.5, 2], absolute error < 2^-21 inside; undefined for x <= 0.
Interval log2(const Interval& x);
// Inherited from exp2(y * log2(x)); undefined where x may be <= 0 (log2(0)
// has no precision, so neither has pow(0, y)).
Interval pow(const Interval& x, const Interval& y);
// Exact.
Interval max(const Interval& a, const Interval& b);
Interval min(const Interval& a, const Interval& b);
// Exact (a sign change): a range across 0 reaches down to 0.
Interval abs(const Interval& x);

// a[0]*b[0] + ... + a[n-1]*b[n-1] as dot() and matrix * vector compute it.
// Implementations may sum in any order and tree shape and fuse any product.
// The result is an open sum region (a later + may regroup with it); for
// n <= 4 closed operands its own set is tightened by bounding every tree
// shape one at a time (dEQP unions the sequential orders; the tree shapes
// of four terms are more).
Interval sumOfProducts(std::span<const Interval> a, std::span<const Interval> b);

}  // namespace snell
