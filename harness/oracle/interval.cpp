#include "oracle/interval.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace snell {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

double nextDown(double x) { return std::nextafter(x, -kInf); }
double nextUp(double x) { return std::nextafter(x, kInf); }

// A real number held as double + error (error-free transformations), so that
// an exact float result is not widened and an inexact one gets exactly the
// two floats around it.
struct Exact {
  double value;
  double error;  // exact = value + error, |error| <= half a double ULP
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

// Largest float <= the exact value: when the double is above the exact value,
// the exact value lies strictly between the double and the one below it.
double floatBelow(Exact x) { return floatAtOrBelow(x.error < 0 ? nextDown(x.value) : x.value); }
double floatAbove(Exact x) { return floatAtOrAbove(x.error > 0 ? nextUp(x.value) : x.value); }

// Any result whose magnitude is below the smallest normal may be flushed.
Interval admitFlushToZero(Interval r) {
  if (r.lo < kFp32MinNormal && r.hi > -kFp32MinNormal) {
    r.lo = std::min(r.lo, 0.0);
    r.hi = std::max(r.hi, 0.0);
  }
  return r;
}

Interval finish(double lo, double hi) {
  if (std::isnan(lo) || std::isnan(hi)) return Interval::unconstrained();
  return admitFlushToZero(Interval(lo, hi));
}

// The lowest value reachable by going `ulps` ULPs below some x in [lo, hi].
// The ULP doubles at each power of two, so for a positive range the first
// power of two above lo may reach lower than lo itself.
double lowestWithinUlps(double lo, double hi, double ulps) {
  if (!std::isfinite(lo)) return lo;
  double lowest = lo - ulps * ulp(lo);
  if (lo >= 0.0) {
    // Below 2^-125 the ULP is 2^-149 throughout (denormals and first binade).
    double power = 0x1p-125;
    if (lo >= power) {
      int exponent = 0;
      std::frexp(lo, &exponent);
      power = std::ldexp(1.0, exponent);
    }
    if (power <= hi) lowest = std::min(lowest, power - ulps * ulp(power));
  }
  return nextDown(lowest);
}

// The floats in [lo, hi]; beyond the float range an overflowing result is
// infinite.
Interval floatsIn(double lo, double hi) {
  const double low = lo < -kFp32Max ? -kInf : floatAtOrAbove(lo);
  const double high = hi > kFp32Max ? kInf : floatAtOrBelow(hi);
  return finish(low, high);
}

}  // namespace

Interval Interval::point(float value) {
  if (std::isnan(value)) return unconstrained();
  return admitFlushToZero(Interval(value, value));
}

Interval Interval::unconstrained() {
  Interval r(-kInf, kInf);
  r.undefined = true;
  return r;
}

Interval operator+(const Interval& a, const Interval& b) {
  if (a.undefined || b.undefined) return Interval::unconstrained();
  return finish(floatBelow(exactSum(a.lo, b.lo)), floatAbove(exactSum(a.hi, b.hi)));
}

Interval operator-(const Interval& a) {
  Interval r(-a.hi, -a.lo);
  r.undefined = a.undefined;
  return r;
}

Interval operator-(const Interval& a, const Interval& b) { return a + (-b); }

Interval operator*(const Interval& a, const Interval& b) {
  if (a.undefined || b.undefined) return Interval::unconstrained();
  const std::array<Exact, 4> products = {exactProduct(a.lo, b.lo), exactProduct(a.lo, b.hi),
                                         exactProduct(a.hi, b.lo), exactProduct(a.hi, b.hi)};
  double lo = kInf;
  double hi = -kInf;
  for (const Exact& p : products) {
    // 0 * inf: a value that may have overflowed times one that may be 0.
    if (std::isnan(p.value)) return Interval::unconstrained();
    lo = std::min(lo, floatBelow(p));
    hi = std::max(hi, floatAbove(p));
  }
  return finish(lo, hi);
}

Interval operator/(const Interval& a, const Interval& b) {
  if (a.undefined || b.undefined) return Interval::unconstrained();
  if (b.lo <= 0.0 && b.hi >= 0.0) return Interval::unconstrained();
  const double smallest = std::min(std::fabs(b.lo), std::fabs(b.hi));
  const double largest = std::max(std::fabs(b.lo), std::fabs(b.hi));
  if (smallest < 0x1p-126 || largest > 0x1p126) return Interval::unconstrained();
  const std::array<double, 4> quotients = {a.lo / b.lo, a.lo / b.hi, a.hi / b.lo, a.hi / b.hi};
  double lo = kInf;
  double hi = -kInf;
  for (double q : quotients) {
    if (std::isnan(q)) return Interval::unconstrained();
    lo = std::min(lo, q);
    hi = std::max(hi, q);
  }
  // The double quotients are within half a double ULP of the exact ones.
  return withinUlps(nextDown(lo), nextUp(hi), 2.5);
}

Truth operator<(const Interval& a, const Interval& b) {
  if (a.undefined || b.undefined) return Truth::Unknown;
  if (a.hi < b.lo) return Truth::True;
  if (a.lo >= b.hi) return Truth::False;
  return Truth::Unknown;
}

bool contains(const Interval& range, float value) {
  if (range.undefined) return true;
  return range.lo <= value && value <= range.hi;  // false for NaN
}

bool contains(const Interval& range, double value) {
  if (range.undefined) return true;
  return range.lo <= value && value <= range.hi;
}

double width(const Interval& range) { return range.hi - range.lo; }

Interval hull(const Interval& a, const Interval& b) {
  if (a.undefined || b.undefined) return Interval::unconstrained();
  return Interval(std::min(a.lo, b.lo), std::max(a.hi, b.hi));
}

Interval withinUlps(double exactLo, double exactHi, double ulps) {
  if (std::isnan(exactLo) || std::isnan(exactHi)) return Interval::unconstrained();
  const double lo = lowestWithinUlps(exactLo, exactHi, ulps);
  const double hi = -lowestWithinUlps(-exactHi, -exactLo, ulps);
  return floatsIn(lo, hi);
}

Interval withinDistance(double exactLo, double exactHi, double distance) {
  if (std::isnan(exactLo) || std::isnan(exactHi)) return Interval::unconstrained();
  return floatsIn(nextDown(exactLo - distance), nextUp(exactHi + distance));
}

}  // namespace snell
