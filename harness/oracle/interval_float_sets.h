#pragma once
// The fp32 grid under Interval: which floats a rounding, a ULP bound or an
// absolute bound can give, computed from double bounds. Every function
// returns a range of floats (lo and hi are floats or infinities) or takes
// ranges whose bounds are already outward.
namespace snell::float_sets {

struct Range {
  double lo;
  double hi;
};

// x with two double ULPs of margin away from 0: for bounds computed with a
// few double operations.
double up(double x);

// 2^-126 when [lo, hi] holds values a flush to zero may change, else 0.
double flushError(double lo, double hi);
// The largest error of one rounding (to either neighbouring float, or a
// flush to 0) of a value in [lo, hi].
double roundingError(double lo, double hi);

// Exact real sum / product / quotient ranges of two ranges, as doubles
// rounded outward (NaN bounds where 0 * inf or inf - inf can occur).
Range exactSumRange(double alo, double ahi, double blo, double bhi);
Range exactProductRange(double alo, double ahi, double blo, double bhi);
Range quotientRange(double alo, double ahi, double blo, double bhi);

// One correctly rounded operation on float ranges, either neighbour: the
// written order's set, exact where the result is a float.
Range roundedSum(double alo, double ahi, double blo, double bhi);
Range roundedProduct(double alo, double ahi, double blo, double bhi);

// The floats a value in [ideal.lo - pending, ideal.hi + pending] rounds to.
Range roundedAround(Range ideal, double pending);

// The floats in [lo, hi]; past the float range an overflowing value may be
// the infinity or the largest finite float of its sign.
Range floatsIn(double lo, double hi);
// The floats strictly inside (lo, hi), with the same overflow rule.
Range strictlyWithin(double lo, double hi);
// The floats within `ulps` Harrison ULPs of some x in [lo, hi].
Range withinUlps(double lo, double hi, double ulps);

// Widens a range that reaches below the smallest normal to hold 0.
Range admitFlushToZero(Range r);

}  // namespace snell::float_sets
