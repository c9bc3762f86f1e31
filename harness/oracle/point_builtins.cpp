#include "oracle/point_builtins.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

#include "oracle/fp32.h"
#include "oracle/fp32_bits.h"
#include "oracle/interval_float_sets.h"
#include "oracle/interval_region_bounds.h"
#include "oracle/interval_sqrt_error.h"
#include "oracle/interval_tree_sum.h"

namespace snell {
namespace {

using float_sets::above;
using float_sets::below;
using float_sets::Range;
using float_sets::up;

constexpr double kInf = std::numeric_limits<double>::infinity();
// Inputs up to 2^16 keep refract's largest monomials (degree 6 in k) below
// 2^96: no intermediate error this road leaves out can be infinite.
constexpr double kLargestInput = 0x1p16;

// Each name below mirrors one piece of interval.cpp or
// interval_builtins.cpp; the comment names it.

// What an open operand (a product or sum its consumer may regroup) hands
// its consumer: its ideal range and its region. Its float set and error
// are never read there, so they are not made.
struct Open {
  Range ideal;
  IntervalRegion region;
};

// A value its consumers take closed: its float set, ideal range and error.
struct Closed {
  Range set;
  Range ideal;
  double err;
};

// interval.cpp's ClosedParts: an operand as an operation sees it.
struct Parts {
  Range ideal;
  double err;
  IntervalRegion region;
};

double maxAbs(Range r) { return std::max(std::fabs(r.lo), std::fabs(r.hi)); }

// closedParts() of a value that is not a constant expression.
Parts closedParts(const Closed& v, PrecisionRules rules) {
  const bool setIsTighter = rules == PrecisionRules::Glsl && std::isfinite(v.set.lo) &&
                            std::isfinite(v.set.hi) &&
                            v.set.hi - v.set.lo <= (v.ideal.hi - v.ideal.lo) + 2.0 * v.err;
  Parts parts{v.ideal, v.err, {}};
  if (setIsTighter) {
    parts.ideal = v.set;
    parts.err = 0.0;
  }
  parts.region = leafRegion(maxAbs(parts.ideal), parts.err, false);
  return parts;
}

// closedParts() of an input (Interval::point of a float that is neither
// NaN nor a denormal), under either rules.
Parts pointParts(double x) { return {{x, x}, 0.0, leafRegion(std::fabs(x), 0.0, false)}; }

// closedParts() of the literal 1.0: a constant power of two.
Parts oneParts() { return {{1.0, 1.0}, 0.0, leafRegion(1.0, 0.0, true)}; }

Parts openParts(const Open& v) { return {v.ideal, 0.0, v.region}; }

Open negated(const Open& v) { return {{-v.ideal.hi, -v.ideal.lo}, v.region}; }

// exactPointProductInto() of two inputs, as far as an open consumer reads
// it. Its exact range is the product itself: two floats multiply exactly
// in double (exactProductRange's error-free transformation would find no
// error, and widen nothing).
Open pointProduct(double x, double y) {
  const double p = x * y;
  return {{p, p},
          productRegion(leafRegion(std::fabs(x), 0.0, false), leafRegion(std::fabs(y), 0.0, false))};
}

// combineInto()'s region, ideal range and pending error. False where the
// general road gives an unconstrained value.
struct Combined {
  Range ideal;
  IntervalRegion region;
  double pending;
};
template <bool add>
bool combine(const Parts& a, const Parts& b, PrecisionRules rules, Combined& c) {
  c.region = add ? sumRegion(a.region, b.region) : productRegion(a.region, b.region);
  if (mayOverflowInside(c.region)) return false;
  c.ideal = add ? float_sets::exactSumRange(a.ideal.lo, a.ideal.hi, b.ideal.lo, b.ideal.hi)
                : float_sets::exactProductRange(a.ideal.lo, a.ideal.hi, b.ideal.lo, b.ideal.hi);
  c.pending = pendingError(c.region, rules);
  return true;
}

// errUnlessOverflowed().
double errUnlessOverflowed(Range ideal, double err) {
  return maxAbs(ideal) + err > kFp32Max ? kInf : err;
}

// combineInto()'s last steps for an operation with an open operand (no
// plain interval to intersect): its set, and writeResult(). False where
// the general road gives an unconstrained value or an unbounded error.
bool closedResult(const Combined& c, Closed& r) {
  const Range set = float_sets::roundedAround(c.ideal, c.pending);
  if (std::isnan(set.lo) || std::isnan(set.hi) || set.lo > set.hi) return false;
  r.set = float_sets::admitFlushToZero(set);
  r.ideal = c.ideal;
  r.err = errUnlessOverflowed(
      c.ideal,
      c.pending + float_sets::roundingError(c.ideal.lo - c.pending, c.ideal.hi + c.pending));
  return std::isfinite(r.err);
}

// leafValue().
bool leafValue(Range set, Range ideal, double err, Closed& r) {
  if (!std::isfinite(err) || std::isnan(set.lo) || std::isnan(set.hi) || std::isnan(ideal.lo) ||
      std::isnan(ideal.hi))
    return false;
  r.set = float_sets::admitFlushToZero(set);
  r.ideal = ideal;
  r.err = errUnlessOverflowed(ideal, err);
  return std::isfinite(r.err);
}

// sumOfProducts(N, I) for n = 2 to 4 exact inputs: the sum region, then
// for three or four terms the bound by tree shapes.
struct Dot {
  Closed value;
  IntervalRegion region;
};
bool dotOfPoints(std::span<const float> N, std::span<const float> I, PrecisionRules rules, Dot& d) {
  const std::size_t n = N.size();
  std::array<Open, 4> products;
  for (std::size_t i = 0; i < n; ++i) products[i] = pointProduct(N[i], I[i]);
  Open sum = products[0];
  Combined c{};
  for (std::size_t i = 1; i < n; ++i) {
    if (!combine<true>(openParts(sum), openParts(products[i]), rules, c)) return false;
    sum = {c.ideal, c.region};
  }
  if (!closedResult(c, d.value)) return false;
  d.region = sum.region;
  if (n < 3) return true;
  std::array<ClosedProduct, 4> closed{};
  for (std::size_t i = 0; i < n; ++i) {
    const Open& p = products[i];
    closed[i] = {p.ideal.lo, p.ideal.hi, p.region.mag - p.region.mag0};
  }
  const double pending = treeSumPending(closed.data(), n);
  Closed& v = d.value;
  if (!(pending < v.err)) return true;
  const Range set =
      float_sets::admitFlushToZero(float_sets::roundedAround({v.ideal.lo, v.ideal.hi}, pending));
  v.set.lo = std::max(v.set.lo, set.lo);
  v.set.hi = std::min(v.set.hi, set.hi);
  v.err = std::min(v.err,
                   pending + float_sets::roundingError(v.ideal.lo - pending, v.ideal.hi + pending));
  return true;
}

// symmetricAboutIdeal() of a value with a finite error: Vulkan's
// [x - E, x + E] for a built-in whose precision is inherited.
void makeSymmetric(Closed& v) {
  const Range symmetric = float_sets::floatsIn(v.ideal.lo - v.err, v.ideal.hi + v.err);
  v.set.lo = std::min(v.set.lo, symmetric.lo);
  v.set.hi = std::max(v.set.hi, symmetric.hi);
}

// The float set of sqrt()'s formula, 1.0 / inversesqrt(x), for x any
// float in [lo, hi], 0 < lo (refract's k): all that sqrt() reads of it.
// The general road also makes each step's ideal range and error, which
// only that step's own error reads, and under Vulkan two more roads to
// the quotient: through the reciprocal (of a dividend of 1: the quotient
// itself, times 1) and the alternative 1.0 * quotient, whose plain
// interval is the quotient's own set. Neither adds a float, and for these
// arguments none of those steps can make the value unconstrained (every
// error is finite, no range reaches 0): they are left out.
bool rootSetOfRange(double lo, double hi, Range& out) {
  // inversesqrt(): 2 ULP about the exact values at the ends.
  const Range inverse = float_sets::admitFlushToZero(
      float_sets::withinUlps(below(1.0 / std::sqrt(hi)), above(1.0 / std::sqrt(lo)), 2.0));
  // divided(1.0, inverse): 2.5 ULP about the exact quotients.
  if (inverse.lo <= 0.0 && inverse.hi >= 0.0) return false;
  const double smallest = std::min(std::fabs(inverse.lo), std::fabs(inverse.hi));
  if (smallest < 0x1p-126 || maxAbs(inverse) > 0x1p126) return false;
  const Range quotients = float_sets::quotientRange(1.0, 1.0, inverse.lo, inverse.hi);
  if (std::isnan(quotients.lo) || std::isnan(quotients.hi)) return false;
  out = float_sets::admitFlushToZero(float_sets::withinUlps(quotients.lo, quotients.hi, 2.5));
  return true;
}

// sqrt() of a closed value whose float set is at or above 0.
template <PrecisionRules rules>
bool sqrtOf(const Closed& xIn, Closed& r) {
  const Parts x = closedParts(xIn, rules);
  const Range xSet = xIn.set;
  if (xSet.lo < 0.0) return false;
  if (xSet.hi <= 0.0) {
    r = {{0.0, 0.0}, {0.0, 0.0}, 0.0};  // Interval::point(0.0f)
    return true;
  }
  Range root{};
  if (!rootSetOfRange(std::max(xSet.lo, kFp32MinDenormal), xSet.hi, root)) return false;
  const double lo = xSet.lo <= 0.0 ? std::min(0.0, root.lo) : root.lo;
  if (!leafValue({lo, root.hi},
                 {below(std::sqrt(std::max(0.0, x.ideal.lo))),
                  above(std::sqrt(std::max(0.0, x.ideal.hi)))},
                 sqrtErrorBound(std::min(xSet.lo, x.ideal.lo), x.err, xSet.hi, lo, root.hi), r))
    return false;
  if constexpr (rules == PrecisionRules::Vulkan) makeSymmetric(r);
  return true;
}

// An operand that is a sum (d, w, t) as a product takes it: closed under
// the GLSL rules (no distributivity); under Vulkan open, unless the
// product's monomials would pass the distribution budget and it has
// several terms.
template <PrecisionRules rules>
Parts sumAsFactor(const Closed& v, const IntervalRegion& region, int otherTerms) {
  if constexpr (rules == PrecisionRules::Glsl) {
    return closedParts(v, rules);
  } else {
    const bool overBudget =
        static_cast<double>(region.terms) * otherTerms > kVulkanDistributionTerms;
    if (overBudget && region.terms > 1) return closedParts(v, rules);
    return {v.ideal, v.err, region};
  }
}

// A component of the built-in's result, the sum `c` closed: its set,
// under Vulkan made symmetric about the ideal value (inherited()). Under
// the GLSL rules the error is not read, so it is not made.
template <PrecisionRules rules>
bool inheritedComponent(const Combined& c, PointBounds& out, std::size_t i) {
  Closed r{};
  if constexpr (rules == PrecisionRules::Glsl) {
    const Range set = float_sets::roundedAround(c.ideal, c.pending);
    if (std::isnan(set.lo) || std::isnan(set.hi) || set.lo > set.hi) return false;
    r.set = float_sets::admitFlushToZero(set);
  } else {
    if (!closedResult(c, r)) return false;
    makeSymmetric(r);
  }
  out.lo[i] = r.set.lo;
  out.hi[i] = r.set.hi;
  return true;
}

// glsl::refract(), n = 2 to 4.
template <PrecisionRules rules>
bool refractWith(std::span<const float> I, std::span<const float> N, float eta,
                                  bool exactTotalInternalReflection, PointRefract& out) {
  const double e = eta;
  // d = dot(N, I), a sum. (Vulkan's inherited() widens its set, which no
  // consumer below reads: each takes its ideal range and error.)
  Dot dot{};
  if (!dotOfPoints(N, I, rules, dot)) return false;
  // k = 1.0 - eta * eta * (1.0 - d * d)
  Combined c{};
  const Parts dFactor = sumAsFactor<rules>(dot.value, dot.region, dot.region.terms);
  if (!combine<false>(dFactor, dFactor, rules, c)) return false;
  const Open dd{c.ideal, c.region};
  Closed w{};
  if (!combine<true>(oneParts(), openParts(negated(dd)), rules, c) || !closedResult(c, w))
    return false;
  const Open ee = pointProduct(e, e);
  if (!combine<false>(openParts(ee), sumAsFactor<rules>(w, c.region, ee.region.terms), rules, c))
    return false;
  const Open m{c.ideal, c.region};
  Closed k{};
  if (!combine<true>(oneParts(), openParts(negated(m)), rules, c) || !closedResult(c, k))
    return false;
  // if (k < 0.0): known only where every allowed value agrees, and the way
  // the exact evaluation took.
  const bool negative = k.set.hi < 0.0;
  if (!negative && !(k.set.lo >= 0.0)) return false;
  if (negative != exactTotalInternalReflection) return false;
  const std::size_t n = I.size();
  out.totalInternalReflection = negative;
  if (negative) {
    for (std::size_t i = 0; i < n; ++i) out.lo[i] = out.hi[i] = 0.0;
    return true;
  }
  // max(k, 0.0): its operands closed, the literal 0.0 exactly 0.
  const Parts kParts = closedParts(k, rules);
  Closed kMax{};
  if (!leafValue({std::max(k.set.lo, 0.0), std::max(k.set.hi, 0.0)},
                 {std::max(kParts.ideal.lo, 0.0), std::max(kParts.ideal.hi, 0.0)},
                 std::max(kParts.err, 0.0), kMax))
    return false;
  Closed root{};
  if (!sqrtOf<rules>(kMax, root)) return false;
  // eta * d + sqrt(k), the product open in the sum.
  const Parts eParts = pointParts(e);
  if (!combine<false>(eParts, sumAsFactor<rules>(dot.value, dot.region, eParts.region.terms), rules,
                      c))
    return false;
  const Open ed{c.ideal, c.region};
  Closed t{};
  if (!combine<true>(openParts(ed), closedParts(root, rules), rules, c) || !closedResult(c, t))
    return false;
  const IntervalRegion tRegion = c.region;
  // eta * I - t * N, each component a sum of two open products.
  for (std::size_t i = 0; i < n; ++i) {
    const Parts nParts = pointParts(N[i]);
    if (!combine<false>(sumAsFactor<rules>(t, tRegion, nParts.region.terms), nParts, rules, c))
      return false;
    const Open tN{c.ideal, c.region};
    if (!combine<true>(openParts(pointProduct(e, I[i])), openParts(negated(tN)), rules, c) ||
        !inheritedComponent<rules>(c, out, i))
      return false;
  }
  return true;
}

// glsl::reflect(), n = 2 to 4: I - 2.0 * dot(N, I) * N.
template <PrecisionRules rules>
bool reflectWith(std::span<const float> I, std::span<const float> N,
                                  PointBounds& out) {
  Dot dot{};
  if (!dotOfPoints(N, I, rules, dot)) return false;
  // The literal 2.0 is a constant power of two: it multiplies exactly.
  const Parts two{{2.0, 2.0}, 0.0, leafRegion(2.0, 0.0, true)};
  Combined c{};
  if (!combine<false>(two, sumAsFactor<rules>(dot.value, dot.region, two.region.terms), rules, c))
    return false;
  const Open twiceD{c.ideal, c.region};
  for (std::size_t i = 0; i < I.size(); ++i) {
    if (!combine<false>(openParts(twiceD), pointParts(N[i]), rules, c)) return false;
    const Open along{c.ideal, c.region};
    if (!combine<true>(pointParts(I[i]), openParts(negated(along)), rules, c) ||
        !inheritedComponent<rules>(c, out, i))
      return false;
  }
  return true;
}

// An input this road mirrors: a float that Interval::point takes as
// itself (not NaN, not a denormal), small enough that no product or sum
// of refract's can reach past the float range.
bool mirrorable(float x) {
  const double a = std::fabs(static_cast<double>(x));
  return a == 0.0 || (a >= kFp32MinNormal && a <= kLargestInput);
}

bool mirrorable(std::span<const float> I, std::span<const float> N) {
  if (I.size() != N.size() || I.size() < 2 || I.size() > 4) return false;
  for (std::size_t i = 0; i < I.size(); ++i)
    if (!mirrorable(I[i]) || !mirrorable(N[i])) return false;
  return true;
}

bool reflectUnder(PrecisionRules rules, std::span<const float> I, std::span<const float> N,
                  PointBounds& out) {
  if (rules == PrecisionRules::Vulkan) return reflectWith<PrecisionRules::Vulkan>(I, N, out);
  return reflectWith<PrecisionRules::Glsl>(I, N, out);
}
bool refractUnder(PrecisionRules rules, std::span<const float> I, std::span<const float> N,
                  float eta, bool exactTotalInternalReflection, PointRefract& out) {
  if (rules == PrecisionRules::Vulkan)
    return refractWith<PrecisionRules::Vulkan>(I, N, eta, exactTotalInternalReflection, out);
  return refractWith<PrecisionRules::Glsl>(I, N, eta, exactTotalInternalReflection, out);
}

// The roads, flattened (GCC at -O2 kept pendingError, roundedAround and
// exactProductRange as calls, a third of the time), once per build.
#define SNELL_POINT_ROADS(suffix, ...)                                                       \
  __VA_ARGS__ bool reflect##suffix(PrecisionRules rules, std::span<const float> I,          \
                                   std::span<const float> N, PointBounds& out) {            \
    return reflectUnder(rules, I, N, out);                                                  \
  }                                                                                         \
  __VA_ARGS__ bool refract##suffix(PrecisionRules rules, std::span<const float> I,          \
                                   std::span<const float> N, float eta, bool exactTir,      \
                                   PointRefract& out) {                                     \
    return refractUnder(rules, I, N, eta, exactTir, out);                                   \
  }
SNELL_POINT_ROADS(Portable, [[gnu::flatten]])
#if SNELL_ORACLE_FMA_BUILD
SNELL_POINT_ROADS(Fma, [[gnu::flatten, gnu::target("fma")]])
#endif
#undef SNELL_POINT_ROADS

}  // namespace

bool reflectOnPoints(std::span<const float> I, std::span<const float> N, PrecisionRules rules,
                     PointBounds& out, OracleBuild build) {
  if (!mirrorable(I, N)) return false;
#if SNELL_ORACLE_FMA_BUILD
  if (build == OracleBuild::Fma) return reflectFma(rules, I, N, out);
#endif
  (void)build;
  return reflectPortable(rules, I, N, out);
}

bool refractOnPoints(std::span<const float> I, std::span<const float> N, float eta,
                     bool exactTotalInternalReflection, PrecisionRules rules, PointRefract& out,
                     OracleBuild build) {
  if (!mirrorable(I, N) || !mirrorable(eta)) return false;
#if SNELL_ORACLE_FMA_BUILD
  if (build == OracleBuild::Fma)
    return refractFma(rules, I, N, eta, exactTotalInternalReflection, out);
#endif
  (void)build;
  return refractPortable(rules, I, N, eta, exactTotalInternalReflection, out);
}

}  // namespace snell
