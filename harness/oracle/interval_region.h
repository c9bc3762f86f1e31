#pragma once
// The open region behind an Interval: a sum or product whose rounding steps
// a compiler may still regroup with the operation that consumes it.
//
// Why a few numbers suffice. Expand any expression built from + - * over
// leaves (inputs, literals, and results of other operations, each with its
// own error bound) into monomials. Every formula that associativity,
// commutativity and distributivity turn it into has the same monomials, and
// its computed value is sum_m c_m * mono_m * prod_j (1 + d_j), one factor
// per rounding on the monomial's path, |d_j| <= u = 2^-23 (either
// neighbouring float), plus an absolute error up to 2^-126 per rounding
// where a result may be flushed or denormal. So for every such formula
//   |computed - ideal| <= gamma(k) * A + (A - A0) + k * 2^-126 * S,
// with A the sum of |monomials| at the leaves' magnitudes plus their error
// bounds, A0 the same without the errors, k the roundings on a path before
// the last one, S the largest product of factor magnitudes a flushed value
// can be multiplied by, and gamma(k) = k u / (1 - k u) (Higham). The last
// rounding is applied exactly, as the choice of the float on either side.
//
// Without distributivity (the GLSL rules) the shape is narrower and the
// bound tighter: a region is a sum of terms that are leaves or products of
// leaves; each product term rounds only relative to its own magnitude, and
// the sum's own roundings relative to the partial sums.
#include <cstdint>

#include "oracle/precision_rules.h"

namespace snell {

struct IntervalRegion {
  enum class Kind : std::uint8_t { Leaf, Product, Sum };
  Kind kind = Kind::Leaf;
  double mag = 0.0;     // A: sum of |monomials|, leaf errors included
  double mag0 = 0.0;    // A0: the same with exact leaves
  double maxSub = 1.0;  // S: max(1, largest product of factor magnitudes)
  int terms = 1;        // monomials in the expansion
  int degree = 1;       // factors per monomial, at most
  // Products (GLSL): factors, and those that are exact powers of two (a
  // multiplication by one rounds nothing, and it may be the last one).
  int factors = 1;
  int exactFactors = 0;
  // Sums (GLSL): the rounding and flush bounds of the product terms, each
  // relative to its own magnitude (a term's last multiplication is fused
  // or rounded inside the sum, so all of its roundings count).
  double termRounding = 0.0;
  double termFlush = 0.0;
};

// Vulkan's distributivity is modelled up to this many monomials in one
// product: past it, the operands of a product that have several terms are
// evaluated first, as without distributivity. The spec sets no limit, but
// its bound for every expansion grows with the number of terms (gamma(k),
// k up to terms + degree, times the sum of |monomials|, which cancellation
// makes far larger than the result) and is useless for a product of a
// dozen sums (about 1300 terms of degree 12 in the blog's diffraction
// listing: an interval 1650 times wider than a dEQP-style one). Compilers
// distribute to form fused multiply-adds, a factor over a sum of a few
// terms; none multiplies a product of sums out. The adversarial machine in
// the tests distributes within the same budget.
inline constexpr int kVulkanDistributionTerms = 8;

inline constexpr double kUnitRoundoff = 0x1p-23;
inline constexpr double kFlushError = 0x1p-126;

// The bounds themselves (gamma(k), the region of a + b and a * b, the
// pending error) are in interval_region_bounds.h, inline for the oracle's
// own + and *.

}  // namespace snell
