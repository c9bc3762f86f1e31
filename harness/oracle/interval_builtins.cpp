#include "oracle/interval_builtins.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

namespace snell {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// libm's exp2, log2 and 1/sqrt in double are within a couple of double ULPs;
// four ULPs outward keep the "exact" range a true bound of the real one.
double below(double x) { return x - std::fabs(x) * 0x1p-50; }
double above(double x) { return x + std::fabs(x) * 0x1p-50; }

double magnitude(const Interval& x) { return std::max(std::fabs(x.lo), std::fabs(x.hi)); }

}  // namespace

Interval inversesqrt(const Interval& x) {
  if (x.undefined || x.lo <= 0.0) return Interval::unconstrained();
  return withinUlps(below(1.0 / std::sqrt(x.hi)), above(1.0 / std::sqrt(x.lo)), 2.0);
}

Interval sqrt(const Interval& x) {
  if (x.undefined || x.lo < 0.0) return Interval::unconstrained();
  const Interval zero = Interval::point(0.0f);
  if (x.hi <= 0.0) return zero;
  // Where x is 0 the formula's 1/inf limit is 0; elsewhere the smallest
  // positive float keeps inversesqrt below 2^75, inside the division rule's
  // range.
  const Interval positive(std::max(x.lo, kFp32MinDenormal), x.hi);
  const Interval root = Interval::point(1.0f) / inversesqrt(positive);
  return x.lo <= 0.0 ? hull(zero, root) : root;
}

Interval exp2(const Interval& x) {
  if (x.undefined) return Interval::unconstrained();
  return withinUlps(below(std::exp2(x.lo)), above(std::exp2(x.hi)), 3.0 + 2.0 * magnitude(x));
}

Interval exp(const Interval& x) {
  if (x.undefined) return Interval::unconstrained();
  return withinUlps(below(std::exp(x.lo)), above(std::exp(x.hi)), 3.0 + 2.0 * magnitude(x));
}

Interval log2(const Interval& x) {
  if (x.undefined || x.lo <= 0.0) return Interval::unconstrained();
  // The rule changes at 0.5 and 2: bound each part by its own rule.
  Interval result;
  bool any = false;
  const auto add = [&](const Interval& part) {
    result = any ? hull(result, part) : part;
    any = true;
  };
  if (x.lo < 0.5) {
    add(withinUlps(below(std::log2(x.lo)), above(std::log2(std::min(x.hi, 0.5))), 3.0));
  }
  if (x.hi >= 0.5 && x.lo <= 2.0) {
    const double lo = std::log2(std::max(x.lo, 0.5));
    const double hi = std::log2(std::min(x.hi, 2.0));
    add(withinDistance(below(lo), above(hi), 0x1p-21));
  }
  if (x.hi > 2.0) {
    add(withinUlps(below(std::log2(std::max(x.lo, 2.0))), above(std::log2(x.hi)), 3.0));
  }
  return result;
}

Interval pow(const Interval& x, const Interval& y) {
  if (x.undefined || y.undefined || x.lo < 0.0) return Interval::unconstrained();
  const bool baseMayBeZero = x.lo <= 0.0;
  if (baseMayBeZero && y.lo <= 0.0) return Interval::unconstrained();
  const Interval zero = Interval::point(0.0f);
  if (x.hi <= 0.0) return zero;
  const Interval positive(std::max(x.lo, kFp32MinDenormal), x.hi);
  const Interval power = exp2(y * log2(positive));
  return baseMayBeZero ? hull(zero, power) : power;
}

Interval max(const Interval& a, const Interval& b) {
  if (a.undefined || b.undefined) return Interval::unconstrained();
  return Interval(std::max(a.lo, b.lo), std::max(a.hi, b.hi));
}

Interval min(const Interval& a, const Interval& b) {
  if (a.undefined || b.undefined) return Interval::unconstrained();
  return Interval(std::min(a.lo, b.lo), std::min(a.hi, b.hi));
}

Interval sumOfProducts(std::span<const Interval> a, std::span<const Interval> b) {
  assert(a.size() == b.size());
  const std::size_t n = a.size();
  double lo = 0.0;
  double hi = 0.0;
  double absSum = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    if (a[i].undefined || b[i].undefined) return Interval::unconstrained();
    const double products[4] = {a[i].lo * b[i].lo, a[i].lo * b[i].hi, a[i].hi * b[i].lo,
                                a[i].hi * b[i].hi};
    double pLo = kInf;
    double pHi = -kInf;
    for (double p : products) {
      if (std::isnan(p)) return Interval::unconstrained();
      pLo = std::min(pLo, p);
      pHi = std::max(pHi, p);
    }
    // Each double step rounds by at most half a double ULP: step outward.
    lo = std::nextafter(lo + std::nextafter(pLo, -kInf), -kInf);
    hi = std::nextafter(hi + std::nextafter(pHi, kInf), kInf);
    absSum = std::nextafter(absSum + magnitude(a[i]) * magnitude(b[i]), kInf);
  }
  const double u = 0x1p-23;
  const double gamma = static_cast<double>(n) * u / (1.0 - static_cast<double>(n) * u);
  // Each of the 2n-1 steps may also flush a result below 2^-126 to 0.
  const double error = above(gamma * absSum) + static_cast<double>(2 * n) * kFp32MinNormal;
  return withinDistance(lo, hi, error);
}

}  // namespace snell
