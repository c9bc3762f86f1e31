#include "oracle/interval_builtins.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <limits>

#include "oracle/fp32_bits.h"
#include "oracle/interval_float_sets.h"
#include "oracle/interval_region_bounds.h"
#include "oracle/interval_sqrt_error.h"
#include "oracle/interval_tree_sum.h"
#include "oracle/precision_rules.h"

namespace snell {
namespace {

using float_sets::above;
using float_sets::below;
using float_sets::up;

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kLn2 = 0.69314718055994530942;

double magnitude(const Interval& x) { return std::max(std::fabs(x.lo), std::fabs(x.hi)); }
double idealMagnitude(const Interval& x) {
  return std::max(std::fabs(x.idealLo), std::fabs(x.idealHi));
}

// The smallest value the computed or the ideal argument can take: the
// derivative bounds of a decreasing-slope function are taken there.
double smallestArgument(const Interval& x) { return std::min(x.lo, x.idealLo); }

Interval folded(Interval r, const Interval& x, double (*f)(double)) {
  if (!x.constant || r.undefined) return r;
  const double value = f(x.folded);
  if (!std::isfinite(value)) return r;
  // Either neighbouring float of the folded double value.
  const double slop = std::fabs(value) * 0x1p-50;
  const float_sets::Range fold =
      float_sets::admitFlushToZero(float_sets::roundedAround({value, value}, slop));
  r.lo = std::min(r.lo, fold.lo);
  r.hi = std::max(r.hi, fold.hi);
  r.err = std::max(r.err, std::max(std::fabs(fold.hi - r.idealLo), std::fabs(r.idealHi - fold.lo)));
  r.region = leafRegion(std::max(std::fabs(r.idealLo), std::fabs(r.idealHi)), r.err, false);
  r.constant = true;
  r.folded = value;
  return r;
}

// Vulkan states the bound of a built-in whose precision is inherited from
// a formula as [x - E, x + E] about the exact result x, E the largest
// distance of any value of the formula: wider than the formula's own set
// on the side where it reaches less far. (glsl/geometric.h's inherited()
// does the same for the geometric built-ins.)
Interval inheritedUnderVulkan(const Interval& r) {
  return currentPrecisionRules() == PrecisionRules::Vulkan ? symmetricAboutIdeal(r) : r;
}

double inverseSqrtOf(double x) { return 1.0 / std::sqrt(x); }
double sqrtOf(double x) { return std::sqrt(x); }
double exp2Of(double x) { return std::exp2(x); }
double expOf(double x) { return std::exp(x); }
double log2Of(double x) { return std::log2(x); }

}  // namespace

Interval inversesqrt(const Interval& xIn) {
  const Interval x = closedView(xIn);
  if (x.undefined || x.lo <= 0.0 || x.idealLo <= 0.0) return Interval::unconstrained();
  // The largest value, made once: its square root and division are among
  // the slowest instructions.
  const double highest = above(1.0 / std::sqrt(x.lo));
  const float_sets::Range set = float_sets::withinUlps(below(1.0 / std::sqrt(x.hi)), highest, 2.0);
  // |1/sqrt(a') - 1/sqrt(a)| <= |a' - a| / (2 m^1.5), m the smallest
  // argument; then 2 ULP of its own at the computed value.
  const double m = smallestArgument(x);
  const double propagated = x.err / (2.0 * m * std::sqrt(m));
  const double own = 2.0 * fp32_bits::gapAbove(highest);
  const Interval r = leafValue(set.lo, set.hi, below(1.0 / std::sqrt(x.idealHi)),
                               above(1.0 / std::sqrt(x.idealLo)), up(up(propagated) + own));
  return folded(r, x, inverseSqrtOf);
}

Interval sqrt(const Interval& xIn) {
  const Interval x = closedView(xIn);
  if (x.undefined || x.lo < 0.0) return Interval::unconstrained();
  if (x.hi <= 0.0) return Interval::point(0.0f);
  // The float set: the formula 1.0 / inversesqrt(x) itself. Where x is 0
  // the formula's 1/inf limit is 0; elsewhere the smallest positive float
  // keeps inversesqrt below 2^75, inside the division rule's range.
  const Interval positive(std::max(x.lo, kFp32MinDenormal), x.hi);
  static const Interval kOne = Interval::point(1.0f);
  const Interval root = kOne / inversesqrt(positive);
  if (root.undefined) return root;
  const double lo = x.lo <= 0.0 ? std::min(0.0, root.lo) : root.lo;
  const Interval r = leafValue(lo, root.hi, below(std::sqrt(std::max(0.0, x.idealLo))),
                               above(std::sqrt(std::max(0.0, x.idealHi))),
                               sqrtErrorBound(smallestArgument(x), x.err, x.hi, lo, root.hi));
  // Inherited from 1.0 / inversesqrt(x).
  return inheritedUnderVulkan(folded(r, x, sqrtOf));
}

Interval exp2(const Interval& xIn) {
  const Interval x = closedView(xIn);
  if (x.undefined) return Interval::unconstrained();
  const double ulps = 3.0 + 2.0 * magnitude(x);
  const float_sets::Range set =
      float_sets::withinUlps(below(std::exp2(x.lo)), above(std::exp2(x.hi)), ulps);
  const double top = above(std::exp2(std::max(x.hi, x.idealHi + x.err)));
  const double propagated = top * kLn2 * x.err;
  const double own = ulps * fp32_bits::gapAbove(top) + float_sets::flushError(set.lo, set.hi);
  const Interval r = leafValue(set.lo, set.hi, below(std::exp2(x.idealLo)),
                               above(std::exp2(x.idealHi)), up(up(propagated) + own));
  return folded(r, x, exp2Of);
}

Interval exp(const Interval& xIn) {
  const Interval x = closedView(xIn);
  if (x.undefined) return Interval::unconstrained();
  const double ulps = 3.0 + 2.0 * magnitude(x);
  const float_sets::Range set =
      float_sets::withinUlps(below(std::exp(x.lo)), above(std::exp(x.hi)), ulps);
  const double top = above(std::exp(std::max(x.hi, x.idealHi + x.err)));
  const double propagated = top * x.err;
  const double own = ulps * fp32_bits::gapAbove(top) + float_sets::flushError(set.lo, set.hi);
  const Interval r = leafValue(set.lo, set.hi, below(std::exp(x.idealLo)),
                               above(std::exp(x.idealHi)), up(up(propagated) + own));
  return folded(r, x, expOf);
}

Interval log2(const Interval& xIn) {
  const Interval x = closedView(xIn);
  if (x.undefined || x.lo <= 0.0 || x.idealLo <= 0.0) return Interval::unconstrained();
  // The rule changes at 0.5 and 2: bound each part by its own rule.
  float_sets::Range set{kInf, -kInf};
  const auto add = [&](const float_sets::Range& part) {
    set.lo = std::min(set.lo, part.lo);
    set.hi = std::max(set.hi, part.hi);
  };
  if (x.lo < 0.5)
    add(float_sets::withinUlps(below(std::log2(x.lo)), above(std::log2(std::min(x.hi, 0.5))), 3.0));
  if (x.hi >= 0.5 && x.lo <= 2.0) {
    const double lo = below(std::log2(std::max(x.lo, 0.5)));
    const double hi = above(std::log2(std::min(x.hi, 2.0)));
    add(float_sets::strictlyWithin(lo - 0x1p-21, hi + 0x1p-21));
  }
  if (x.hi > 2.0)
    add(float_sets::withinUlps(below(std::log2(std::max(x.lo, 2.0))), above(std::log2(x.hi)), 3.0));
  const double m = smallestArgument(x);
  const double propagated = x.err / (kLn2 * m);
  const double own =
      std::max(3.0 * fp32_bits::gapAbove(std::max(std::fabs(set.lo), std::fabs(set.hi))), 0x1p-21);
  const Interval r = leafValue(set.lo, set.hi, below(std::log2(x.idealLo)),
                               above(std::log2(x.idealHi)), up(up(propagated) + own));
  return folded(r, x, log2Of);
}

Interval pow(const Interval& x, const Interval& y) {
  // The precision is inherited from exp2(y * log2(x)), and log2(0) has
  // none: where the base may be 0 (or a denormal that is flushed) the
  // result is open, pow(0, y > 0) = 0 of the function's definition
  // included.
  if (x.undefined || y.undefined || x.lo <= 0.0) return Interval::unconstrained();
  return inheritedUnderVulkan(exp2(y * log2(x)));
}

Interval max(const Interval& aIn, const Interval& bIn) {
  const Interval a = closedView(aIn);
  const Interval b = closedView(bIn);
  if (a.undefined || b.undefined) return Interval::unconstrained();
  // |max(a', b') - max(a, b)| <= max(|a' - a|, |b' - b|).
  return leafValue(std::max(a.lo, b.lo), std::max(a.hi, b.hi), std::max(a.idealLo, b.idealLo),
                   std::max(a.idealHi, b.idealHi), std::max(a.err, b.err));
}

Interval min(const Interval& aIn, const Interval& bIn) {
  const Interval a = closedView(aIn);
  const Interval b = closedView(bIn);
  if (a.undefined || b.undefined) return Interval::unconstrained();
  return leafValue(std::min(a.lo, b.lo), std::min(a.hi, b.hi), std::min(a.idealLo, b.idealLo),
                   std::min(a.idealHi, b.idealHi), std::max(a.err, b.err));
}

Interval abs(const Interval& xIn) {
  const Interval x = closedView(xIn);
  if (x.undefined) return x;
  if (x.lo >= 0.0 && x.idealLo >= 0.0) return x;
  if (x.hi <= 0.0 && x.idealHi <= 0.0) return -x;
  const double idealLo = x.idealLo <= 0.0 && x.idealHi >= 0.0
                             ? 0.0
                             : std::min(std::fabs(x.idealLo), std::fabs(x.idealHi));
  const double lo = x.lo <= 0.0 && x.hi >= 0.0 ? 0.0 : std::min(std::fabs(x.lo), std::fabs(x.hi));
  return leafValue(lo, magnitude(x), idealLo, idealMagnitude(x), x.err);
}

Interval sumOfProducts(std::span<const Interval> a, std::span<const Interval> b) {
  assert(a.size() == b.size() && !a.empty());
  const std::size_t n = a.size();
  // Of each product, what the bound by trees below needs: its ideal range
  // and the error it carries from its operands (a dot product or a matrix
  // row has at most four terms; past four the bound is not made).
  std::array<ClosedProduct, 4> products;
  Interval sum;
  for (std::size_t i = 0; i < n; ++i) {
    const Interval p = a[i] * b[i];
    if (i < products.size()) products[i] = {p.idealLo, p.idealHi, p.region.mag - p.region.mag0};
    sum = i == 0 ? p : sum + p;
  }
  if (sum.undefined || n < 3 || n > 4) return sum;
  // Where every factor is closed, the products are the terms and every
  // order of their sum can be bounded one tree at a time: tighter than the
  // region's bound, which must also hold for whatever later joins the sum.
  for (std::size_t i = 0; i < n; ++i)
    if (a[i].region.kind != IntervalRegion::Kind::Leaf ||
        b[i].region.kind != IntervalRegion::Kind::Leaf)
      return sum;
  const double pending = treeSumPending(products.data(), n);
  if (!(pending < sum.err)) return sum;
  float_sets::Range set = float_sets::roundedAround({sum.idealLo, sum.idealHi}, pending);
  set = float_sets::admitFlushToZero(set);
  sum.lo = std::max(sum.lo, set.lo);
  sum.hi = std::min(sum.hi, set.hi);
  sum.err = std::min(
      sum.err, pending + float_sets::roundingError(sum.idealLo - pending, sum.idealHi + pending));
  return sum;
}

}  // namespace snell
