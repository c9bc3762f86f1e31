#include "oracle/interval_float_sets.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

#include "oracle/fp32.h"

namespace snell::float_sets {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double nextDown(double x) { return std::nextafter(x, -kInf); }
double nextUp(double x) { return std::nextafter(x, kInf); }

// A real number held as double + error (error-free transformations), so that
// an exact float result is not widened and an inexact one gets exactly the
// two floats around it.
struct Exact {
  double value;
  double error;  // exact = value + error
};

Exact exactSum(double a, double b) {
  const double s = a + b;
  if (!std::isfinite(s)) return {s, 0.0};
  const double bVirtual = s - a;
  return {s, (a - (s - bVirtual)) + (b - bVirtual)};
}

Exact exactProduct(double a, double b) {
  const double p = a * b;
  if (!std::isfinite(p)) return {p, 0.0};
  return {p, std::fma(a, b, -p)};
}

double doubleBelow(Exact x) { return x.error < 0 ? nextDown(x.value) : x.value; }
double doubleAbove(Exact x) { return x.error > 0 ? nextUp(x.value) : x.value; }

bool isPowerOfTwo(double x) {
  int exponent = 0;
  return x > 0 && std::frexp(x, &exponent) == 0.5;
}

// The lowest value reachable by going `ulps` Harrison ULPs below some x in
// [lo, hi]. Just above a power of two the gap doubles, so the first power
// of two at or above lo (if the range reaches past it) may reach lower than
// lo itself; below 2^-125 the gap is 2^-149 throughout.
double lowestWithinUlps(double lo, double hi, double ulps) {
  if (!std::isfinite(lo)) return lo;
  double lowest = lo - ulps * ulp(lo);
  if (lo >= 0.0) {
    double power = 0x1p-125;
    if (lo >= power) {
      int exponent = 0;
      std::frexp(lo, &exponent);
      power = isPowerOfTwo(lo) ? lo : std::ldexp(1.0, exponent);
    }
    if (power < hi) lowest = std::min(lowest, power - ulps * gapAbove(power));
  }
  return nextDown(lowest);
}

}  // namespace

double up(double x) { return x + std::fabs(x) * 0x1p-51; }

double flushError(double lo, double hi) {
  const bool reachesDenormals = lo < kFp32MinNormal && hi > -kFp32MinNormal;
  const bool onlyZero = lo == 0.0 && hi == 0.0;
  return reachesDenormals && !onlyZero ? kFp32MinNormal : 0.0;
}

double roundingError(double lo, double hi) {
  return gapAbove(std::max(std::fabs(lo), std::fabs(hi))) + flushError(lo, hi);
}

Range exactSumRange(double alo, double ahi, double blo, double bhi) {
  return {doubleBelow(exactSum(alo, blo)), doubleAbove(exactSum(ahi, bhi))};
}

Range exactProductRange(double alo, double ahi, double blo, double bhi) {
  const std::array<Exact, 4> products = {exactProduct(alo, blo), exactProduct(alo, bhi),
                                         exactProduct(ahi, blo), exactProduct(ahi, bhi)};
  Range r{kInf, -kInf};
  for (const Exact& p : products) {
    if (std::isnan(p.value)) return {kNaN, kNaN};
    r.lo = std::min(r.lo, doubleBelow(p));
    r.hi = std::max(r.hi, doubleAbove(p));
  }
  return r;
}

Range quotientRange(double alo, double ahi, double blo, double bhi) {
  const std::array<std::pair<double, double>, 4> operands = {
      std::pair{alo, blo}, std::pair{alo, bhi}, std::pair{ahi, blo}, std::pair{ahi, bhi}};
  Range r{kInf, -kInf};
  for (const auto& [a, b] : operands) {
    const double q = a / b;
    if (std::isnan(q)) return {kNaN, kNaN};
    // a - q*b is exact in one fma (barring underflow), so its sign says on
    // which side of q the exact quotient lies: an exact quotient stays a
    // point, and a power of two is not widened into the larger gap above it.
    const double remainder = std::fma(-q, b, a);
    const bool remainderExact = std::isfinite(q) && std::fabs(a) > 0x1p-969;
    // The sign of (exact - q) = remainder / b, without a division that might underflow.
    const double exactMinusQ = !remainderExact ? kNaN
                               : remainder == 0.0 ? 0.0
                               : (remainder > 0.0) == (b > 0.0) ? 1.0
                                                                : -1.0;
    const double below = exactMinusQ >= 0.0 ? q : nextDown(q);
    const double above = exactMinusQ <= 0.0 ? q : nextUp(q);
    r.lo = std::min(r.lo, below);
    r.hi = std::max(r.hi, above);
  }
  return r;
}

Range roundedSum(double alo, double ahi, double blo, double bhi) {
  const Exact low = exactSum(alo, blo);
  const Exact high = exactSum(ahi, bhi);
  if (std::isnan(low.value) || std::isnan(high.value)) return {kNaN, kNaN};
  return {floatAtOrBelow(doubleBelow(low)), floatAtOrAbove(doubleAbove(high))};
}

Range roundedProduct(double alo, double ahi, double blo, double bhi) {
  const Range exact = exactProductRange(alo, ahi, blo, bhi);
  if (std::isnan(exact.lo)) return exact;
  return {floatAtOrBelow(exact.lo), floatAtOrAbove(exact.hi)};
}

Range roundedAround(Range ideal, double pending) {
  if (std::isnan(ideal.lo) || std::isnan(ideal.hi) || std::isnan(pending)) return {kNaN, kNaN};
  if (pending == 0.0) return {floatAtOrBelow(ideal.lo), floatAtOrAbove(ideal.hi)};
  return {floatAtOrBelow(nextDown(ideal.lo - pending)), floatAtOrAbove(nextUp(ideal.hi + pending))};
}

Range floatsIn(double lo, double hi) {
  if (std::isnan(lo) || std::isnan(hi)) return {kNaN, kNaN};
  const double low = lo < -kFp32Max ? -kInf : std::min(floatAtOrAbove(lo), kFp32Max);
  const double high = hi > kFp32Max ? kInf : std::max(floatAtOrBelow(hi), -kFp32Max);
  return admitFlushToZero({low, high});
}

Range strictlyWithin(double lo, double hi) {
  if (std::isnan(lo) || std::isnan(hi)) return {kNaN, kNaN};
  double low = lo < -kFp32Max ? -kInf : floatAtOrAbove(lo);
  if (low == lo)
    low = std::nextafter(static_cast<float>(low), std::numeric_limits<float>::infinity());
  double high = hi > kFp32Max ? kInf : floatAtOrBelow(hi);
  if (high == hi)
    high = std::nextafter(static_cast<float>(high), -std::numeric_limits<float>::infinity());
  return admitFlushToZero({std::min(low, kFp32Max), std::max(high, -kFp32Max)});
}

Range withinUlps(double lo, double hi, double ulps) {
  if (std::isnan(lo) || std::isnan(hi)) return {kNaN, kNaN};
  return floatsIn(lowestWithinUlps(lo, hi, ulps), -lowestWithinUlps(-hi, -lo, ulps));
}

Range admitFlushToZero(Range r) {
  if (r.lo < kFp32MinNormal && r.hi > -kFp32MinNormal) {
    r.lo = std::min(r.lo, 0.0);
    r.hi = std::max(r.hi, 0.0);
  }
  return r;
}

}  // namespace snell::float_sets
