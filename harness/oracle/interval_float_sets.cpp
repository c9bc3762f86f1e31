#include "oracle/interval_float_sets.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>

namespace snell::float_sets {
namespace {

using detail::kInf;
using detail::kNaN;
using fp32_bits::nextDown;
using fp32_bits::nextUp;

// The lowest value reachable by going `ulps` Harrison ULPs below some x in
// [lo, hi]. Just above a power of two the gap doubles, so the first power
// of two at or above lo (if the range reaches past it) may reach lower than
// lo itself; below 2^-125 the gap is 2^-149 throughout.
double lowestWithinUlps(double lo, double hi, double ulps) {
  if (!std::isfinite(lo)) return lo;
  double lowest = lo - ulps * fp32_bits::ulp(lo);
  if (lo >= 0.0) {
    double power = 0x1p-125;
    if (lo >= power) {
      power = fp32_bits::isPositivePowerOfTwo(lo) ? lo : fp32_bits::powerOfTwoAbove(lo);
    }
    if (power < hi) lowest = std::min(lowest, power - ulps * fp32_bits::gapAbove(power));
  }
  return nextDown(lowest);
}

}  // namespace

Range quotientRange(double alo, double ahi, double blo, double bhi) {
  const std::array<std::pair<double, double>, 4> operands = {
      std::pair{alo, blo}, std::pair{alo, bhi}, std::pair{ahi, blo}, std::pair{ahi, bhi}};
  // A point (the same bits at both ends) repeats a quotient: a point
  // dividend, such as sqrt's 1.0 / inversesqrt(x), needs two of the four,
  // two points one. The repeats would give the same bounds again.
  const bool pointDividend = fp32_bits::bitsOf(alo) == fp32_bits::bitsOf(ahi);
  const bool pointDivisor = fp32_bits::bitsOf(blo) == fp32_bits::bitsOf(bhi);
  const std::size_t count = pointDividend ? (pointDivisor ? 1 : 2) : 4;
  // With a point divisor and a range dividend, the distinct pairs are the
  // first and the third.
  const std::size_t step = !pointDividend && pointDivisor ? 2 : 1;
  Range r{kInf, -kInf};
  for (std::size_t k = 0; k < count; k += step) {
    const auto& [a, b] = operands[k];
    const double q = a / b;
    if (std::isnan(q)) return {kNaN, kNaN};
    // a - q*b is exact in one fma (barring underflow), so its sign says on
    // which side of q the exact quotient lies: an exact quotient stays a
    // point, and a power of two is not widened into the larger gap above it.
    const double remainder = std::fma(-q, b, a);
    const bool remainderExact = std::isfinite(q) && std::fabs(a) > 0x1p-969;
    // The sign of (exact - q) = remainder / b, without a division that might underflow.
    const double exactMinusQ = !remainderExact                  ? kNaN
                               : remainder == 0.0               ? 0.0
                               : (remainder > 0.0) == (b > 0.0) ? 1.0
                                                                : -1.0;
    const double below = exactMinusQ >= 0.0 ? q : nextDown(q);
    const double above = exactMinusQ <= 0.0 ? q : nextUp(q);
    r.lo = std::min(r.lo, below);
    r.hi = std::max(r.hi, above);
  }
  return r;
}

Range floatsIn(double lo, double hi) {
  if (std::isnan(lo) || std::isnan(hi)) return {kNaN, kNaN};
  const double low = lo < -kFp32Max ? -kInf : std::min(fp32_bits::floatAtOrAbove(lo), kFp32Max);
  const double high = hi > kFp32Max ? kInf : std::max(fp32_bits::floatAtOrBelow(hi), -kFp32Max);
  return admitFlushToZero({low, high});
}

Range strictlyWithin(double lo, double hi) {
  if (std::isnan(lo) || std::isnan(hi)) return {kNaN, kNaN};
  double low = lo < -kFp32Max ? -kInf : fp32_bits::floatAtOrAbove(lo);
  if (low == lo) low = fp32_bits::nextUpFloat(static_cast<float>(low));
  double high = hi > kFp32Max ? kInf : fp32_bits::floatAtOrBelow(hi);
  if (high == hi) high = fp32_bits::nextDownFloat(static_cast<float>(high));
  return admitFlushToZero({std::min(low, kFp32Max), std::max(high, -kFp32Max)});
}

Range withinUlps(double lo, double hi, double ulps) {
  if (std::isnan(lo) || std::isnan(hi)) return {kNaN, kNaN};
  return floatsIn(lowestWithinUlps(lo, hi, ulps), -lowestWithinUlps(-hi, -lo, ulps));
}

}  // namespace snell::float_sets
