#include "widths/deqp_interval.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "widths/fp32_grid.h"

namespace snell::widths {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

DeqpValue undefinedValue() { return {-kInf, kInf, true}; }

bool anyUndefined(const DeqpValue& a, const DeqpValue& b) { return a.undefined || b.undefined; }

// The floats within `ulps` ULP of some exact value in [lo, hi]; lo and hi
// already enclose the exact range.
DeqpValue withinUlps(double lo, double hi, double ulps) {
  const double low = lo - ulps * std::max(ulpOf(lo), ulpOf(std::nextafter(lo, -kInf)));
  const double high = hi + ulps * std::max(ulpOf(hi), ulpOf(std::nextafter(hi, kInf)));
  return roundedOutward(std::nextafter(low, -kInf), std::nextafter(high, kInf));
}

// An enclosure of f over [lo, hi] for a monotonic f computed in double
// (a few double ULP of error, far below one fp32 ULP).
template <class F>
void monotonic(F f, double lo, double hi, double* outLo, double* outHi) {
  double a = f(lo);
  double b = f(hi);
  if (a > b) std::swap(a, b);
  *outLo = std::nextafter(std::nextafter(a, -kInf), -kInf);
  *outHi = std::nextafter(std::nextafter(b, kInf), kInf);
}

}  // namespace

DeqpValue roundedOutward(double lo, double hi) {
  if (std::isnan(lo) || std::isnan(hi)) return undefinedValue();
  DeqpValue r{floatDown(lo), floatUp(hi), false};
  if (std::isinf(r.lo) || std::isinf(r.hi)) return undefinedValue();
  if (r.lo < kMinNormal && r.hi > -kMinNormal) {
    r.lo = std::min(r.lo, 0.0);
    r.hi = std::max(r.hi, 0.0);
  }
  return r;
}

DeqpValue DeqpArith::add(const Value& a, const Value& b) {
  if (anyUndefined(a, b)) return undefinedValue();
  return roundedOutward(addDown(a.lo, b.lo), addUp(a.hi, b.hi));
}

namespace {
void productRange(const DeqpValue& a, const DeqpValue& b, double* lo, double* hi) {
  *lo = std::min(
      {mulDown(a.lo, b.lo), mulDown(a.lo, b.hi), mulDown(a.hi, b.lo), mulDown(a.hi, b.hi)});
  *hi = std::max({mulUp(a.lo, b.lo), mulUp(a.lo, b.hi), mulUp(a.hi, b.lo), mulUp(a.hi, b.hi)});
}
}  // namespace

DeqpValue DeqpArith::mul(const Value& a, const Value& b) {
  if (anyUndefined(a, b)) return undefinedValue();
  double lo = 0, hi = 0;
  productRange(a, b, &lo, &hi);
  return roundedOutward(lo, hi);
}

DeqpValue DeqpArith::fma(const Value& a, const Value& b, const Value& c) {
  if (anyUndefined(a, b) || c.undefined) return undefinedValue();
  double lo = 0, hi = 0;
  productRange(a, b, &lo, &hi);
  return roundedOutward(addDown(lo, c.lo), addUp(hi, c.hi));
}

DeqpValue DeqpArith::choose(std::span<const Value> ways) {
  Value r = ways[0];
  for (const Value& way : ways) {
    if (way.undefined) return undefinedValue();
    r.lo = std::min(r.lo, way.lo);
    r.hi = std::max(r.hi, way.hi);
  }
  return r;
}

DeqpValue DeqpArith::div(const Value& a, const Value& b) {
  if (anyUndefined(a, b)) return undefinedValue();
  const double smallest = std::min(std::fabs(b.lo), std::fabs(b.hi));
  const double largest = std::max(std::fabs(b.lo), std::fabs(b.hi));
  if ((b.lo <= 0 && b.hi >= 0) || smallest < 0x1p-126 || largest > 0x1p126) return undefinedValue();
  const double q[] = {a.lo / b.lo, a.lo / b.hi, a.hi / b.lo, a.hi / b.hi};
  const double lo = std::nextafter(*std::min_element(q, q + 4), -kInf);
  const double hi = std::nextafter(*std::max_element(q, q + 4), kInf);
  return withinUlps(lo, hi, 2.5);
}

DeqpValue DeqpArith::inversesqrt(const Value& x) {
  if (x.undefined || x.lo <= 0) return undefinedValue();
  double lo = 0, hi = 0;
  monotonic([](double v) { return 1.0 / std::sqrt(v); }, x.lo, x.hi, &lo, &hi);
  return withinUlps(lo, hi, 2.0);
}

// 1 / inversesqrt(x); sqrt(0) = 0, the formula's limit, and the positive
// part is taken from the smallest normal up (a denormal may be flushed).
DeqpValue DeqpArith::sqrt(const Value& x) {
  if (x.undefined || x.hi < 0) return undefinedValue();
  const Value one = point(1.0f);
  if (x.lo > 0) return div(one, inversesqrt(x));
  const Value zero = point(0.0f);
  if (x.hi < kMinNormal) return Value{0.0, floatUp(std::sqrt(x.hi) * 1.001), false};
  const Value positive = div(one, inversesqrt(Value{kMinNormal, x.hi, false}));
  const Value both[] = {zero, positive};
  return x.lo < 0 ? undefinedValue() : choose(both);
}

DeqpValue DeqpArith::exp2(const Value& x) {
  if (x.undefined) return undefinedValue();
  double lo = 0, hi = 0;
  monotonic([](double v) { return std::exp2(v); }, x.lo, x.hi, &lo, &hi);
  return withinUlps(lo, hi, 3.0 + 2.0 * std::max(std::fabs(x.lo), std::fabs(x.hi)));
}

DeqpValue DeqpArith::exp(const Value& x) {
  if (x.undefined) return undefinedValue();
  double lo = 0, hi = 0;
  monotonic([](double v) { return std::exp(v); }, x.lo, x.hi, &lo, &hi);
  return withinUlps(lo, hi, 3.0 + 2.0 * std::max(std::fabs(x.lo), std::fabs(x.hi)));
}

DeqpValue DeqpArith::log2(const Value& x) {
  if (x.undefined || x.lo <= 0) return undefinedValue();
  double lo = 0, hi = 0;
  monotonic([](double v) { return std::log2(v); }, x.lo, x.hi, &lo, &hi);
  Value r = withinUlps(lo, hi, 3.0);
  if (x.lo <= 2.0 && x.hi >= 0.5) {
    const Value absolute = roundedOutward(lo - 0x1p-21, hi + 0x1p-21);
    const Value both[] = {r, absolute};
    r = choose(both);
  }
  return r;
}

DeqpValue DeqpArith::pow(const Value& x, const Value& y) {
  if (x.undefined || y.undefined || x.lo < 0) return undefinedValue();
  if (x.lo > 0) return exp2(mul(y, log2(x)));
  if (y.lo <= 0) return undefinedValue();
  const Value zero = point(0.0f);
  if (x.hi == 0) return zero;
  const Value positive = exp2(mul(y, log2(Value{0x1p-149, x.hi, false})));
  const Value both[] = {zero, positive};
  return choose(both);
}

DeqpValue DeqpArith::max(const Value& a, const Value& b) {
  if (anyUndefined(a, b)) return undefinedValue();
  return {std::max(a.lo, b.lo), std::max(a.hi, b.hi), false};
}

DeqpValue DeqpArith::min(const Value& a, const Value& b) {
  if (anyUndefined(a, b)) return undefinedValue();
  return {std::min(a.lo, b.lo), std::min(a.hi, b.hi), false};
}

DeqpValue DeqpArith::abs(const Value& x) {
  if (x.undefined) return undefinedValue();
  if (x.lo >= 0) return x;
  if (x.hi <= 0) return neg(x);
  return {0.0, std::max(-x.lo, x.hi), false};
}

Truth DeqpArith::less(const Value& a, const Value& b) {
  if (anyUndefined(a, b)) return Truth::Unknown;
  if (a.hi < b.lo) return Truth::True;
  if (a.lo >= b.hi) return Truth::False;
  return Truth::Unknown;
}

}  // namespace snell::widths
