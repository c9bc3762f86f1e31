#pragma once
// The fp32 grid under Interval: which floats a rounding, a ULP bound or an
// absolute bound can give, computed from double bounds. Every function
// returns a range of floats (lo and hi are floats or infinities) or takes
// ranges whose bounds are already outward.
//
// Internal to the oracle library (its .cpp files are compiled without GCC's
// SLP vectorizer: see fp32_bits.h). The small functions that every + and *
// calls are defined inline below the declarations.
#include <algorithm>
#include <cmath>
#include <limits>

#include "oracle/fp32.h"
#include "oracle/fp32_bits.h"

namespace snell::float_sets {

struct Range {
  double lo;
  double hi;
};

// x with two double ULPs of margin away from 0: for bounds computed with a
// few double operations.
inline double up(double x);
// x four double ULPs below and above: libm's exp2, log2, sqrt and 1/sqrt
// in double are within a couple of double ULPs, so these keep an "exact"
// range made with them a true bound of the real one.
inline double below(double x);
inline double above(double x);

// 2^-126 when [lo, hi] holds values a flush to zero may change, else 0.
inline double flushError(double lo, double hi);
// The largest error of one rounding (to either neighbouring float, or a
// flush to 0) of a value in [lo, hi].
inline double roundingError(double lo, double hi);

// Exact real sum / product / quotient ranges of two ranges, as doubles
// rounded outward (NaN bounds where 0 * inf or inf - inf can occur).
inline Range exactSumRange(double alo, double ahi, double blo, double bhi);
inline Range exactProductRange(double alo, double ahi, double blo, double bhi);
Range quotientRange(double alo, double ahi, double blo, double bhi);

// One correctly rounded operation on float ranges, either neighbour: the
// written order's set, exact where the result is a float.
inline Range roundedSum(double alo, double ahi, double blo, double bhi);
inline Range roundedProduct(double alo, double ahi, double blo, double bhi);

// The floats a value in [ideal.lo - pending, ideal.hi + pending] rounds to.
inline Range roundedAround(Range ideal, double pending);

// The floats in [lo, hi]; past the float range an overflowing value may be
// the infinity or the largest finite float of its sign.
Range floatsIn(double lo, double hi);
// The floats strictly inside (lo, hi), with the same overflow rule.
Range strictlyWithin(double lo, double hi);
// The floats within `ulps` Harrison ULPs of some x in [lo, hi].
Range withinUlps(double lo, double hi, double ulps);

// Widens a range that reaches below the smallest normal to hold 0.
inline Range admitFlushToZero(Range r);

// ---- inline definitions ----

namespace detail {

inline constexpr double kInf = std::numeric_limits<double>::infinity();
inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// A real number held as double + error (error-free transformations), so that
// an exact float result is not widened and an inexact one gets exactly the
// two floats around it.
struct Exact {
  double value;
  double error;  // exact = value + error
};

inline Exact exactSum(double a, double b) {
  const double s = a + b;
  if (!std::isfinite(s)) return {s, 0.0};
  const double bVirtual = s - a;
  return {s, (a - (s - bVirtual)) + (b - bVirtual)};
}

inline Exact exactProduct(double a, double b) {
  const double p = a * b;
  if (!std::isfinite(p)) return {p, 0.0};
  return {p, std::fma(a, b, -p)};
}

inline double doubleBelow(Exact x) { return x.error < 0 ? fp32_bits::nextDown(x.value) : x.value; }
inline double doubleAbove(Exact x) { return x.error > 0 ? fp32_bits::nextUp(x.value) : x.value; }

}  // namespace detail

inline double up(double x) { return x + std::fabs(x) * 0x1p-51; }
inline double below(double x) { return x - std::fabs(x) * 0x1p-50; }
inline double above(double x) { return x + std::fabs(x) * 0x1p-50; }

inline double flushError(double lo, double hi) {
  const bool reachesDenormals = lo < kFp32MinNormal && hi > -kFp32MinNormal;
  const bool onlyZero = lo == 0.0 && hi == 0.0;
  return reachesDenormals && !onlyZero ? kFp32MinNormal : 0.0;
}

inline double roundingError(double lo, double hi) {
  return fp32_bits::gapAbove(std::max(std::fabs(lo), std::fabs(hi))) + flushError(lo, hi);
}

inline Range exactSumRange(double alo, double ahi, double blo, double bhi) {
  return {detail::doubleBelow(detail::exactSum(alo, blo)),
          detail::doubleAbove(detail::exactSum(ahi, bhi))};
}

inline Range exactProductRange(double alo, double ahi, double blo, double bhi) {
  // A point (the same bits at both ends, so the same signed zero) repeats
  // products: two points give four copies of one, a point and a range two
  // copies of two. The copies would give the same bounds again.
  const bool pointA = fp32_bits::bitsOf(alo) == fp32_bits::bitsOf(ahi);
  const bool pointB = fp32_bits::bitsOf(blo) == fp32_bits::bitsOf(bhi);
  if (pointA && pointB) {
    const detail::Exact p = detail::exactProduct(alo, blo);
    if (std::isnan(p.value)) return {detail::kNaN, detail::kNaN};
    return {detail::doubleBelow(p), detail::doubleAbove(p)};
  }
  // Two floats multiply exactly in double (at most 48 significant bits, and
  // no product of normal floats outside 2^-252 to 2^256): the products are
  // their own bounds, with no error to find (an fma each, a call into libm).
  if (fp32_bits::isZeroOrNormalFloat(alo) && fp32_bits::isZeroOrNormalFloat(ahi) &&
      fp32_bits::isZeroOrNormalFloat(blo) && fp32_bits::isZeroOrNormalFloat(bhi)) {
    const double p[4] = {alo * blo, alo * bhi, ahi * blo, ahi * bhi};
    return {std::min({p[0], p[1], p[2], p[3]}), std::max({p[0], p[1], p[2], p[3]})};
  }
  detail::Exact products[4];
  int count = 0;
  products[count++] = detail::exactProduct(alo, blo);
  if (!pointB) products[count++] = detail::exactProduct(alo, bhi);
  if (!pointA) products[count++] = detail::exactProduct(ahi, blo);
  if (!pointA && !pointB) products[count++] = detail::exactProduct(ahi, bhi);
  Range r{detail::kInf, -detail::kInf};
  for (int k = 0; k < count; ++k) {
    const detail::Exact& p = products[k];
    if (std::isnan(p.value)) return {detail::kNaN, detail::kNaN};
    r.lo = std::min(r.lo, detail::doubleBelow(p));
    r.hi = std::max(r.hi, detail::doubleAbove(p));
  }
  return r;
}

inline Range roundedSum(double alo, double ahi, double blo, double bhi) {
  const detail::Exact low = detail::exactSum(alo, blo);
  const detail::Exact high = detail::exactSum(ahi, bhi);
  if (std::isnan(low.value) || std::isnan(high.value)) return {detail::kNaN, detail::kNaN};
  return {fp32_bits::floatAtOrBelow(detail::doubleBelow(low)),
          fp32_bits::floatAtOrAbove(detail::doubleAbove(high))};
}

inline Range roundedProduct(double alo, double ahi, double blo, double bhi) {
  const Range exact = exactProductRange(alo, ahi, blo, bhi);
  if (std::isnan(exact.lo)) return exact;
  return {fp32_bits::floatAtOrBelow(exact.lo), fp32_bits::floatAtOrAbove(exact.hi)};
}

inline Range roundedAround(Range ideal, double pending) {
  if (std::isnan(ideal.lo) || std::isnan(ideal.hi) || std::isnan(pending))
    return {detail::kNaN, detail::kNaN};
  if (pending == 0.0)
    return {fp32_bits::floatAtOrBelow(ideal.lo), fp32_bits::floatAtOrAbove(ideal.hi)};
  return {fp32_bits::floatAtOrBelow(fp32_bits::nextDown(ideal.lo - pending)),
          fp32_bits::floatAtOrAbove(fp32_bits::nextUp(ideal.hi + pending))};
}

inline Range admitFlushToZero(Range r) {
  if (r.lo < kFp32MinNormal && r.hi > -kFp32MinNormal) {
    r.lo = std::min(r.lo, 0.0);
    r.hi = std::max(r.hi, 0.0);
  }
  return r;
}

}  // namespace snell::float_sets
