#pragma once
// The bounds of oracle/interval_region.h: inline, because every + and * of
// an Interval computes them. Internal to the oracle library (included by
// its .cpp files only).
#include <algorithm>
#include <array>
#include <cmath>

#include "oracle/fp32_bits.h"
#include "oracle/interval_region.h"

namespace snell {
namespace region_detail {

// gamma(k) for small k, computed once: the same operations as gammaBound's,
// at compile time (IEEE double arithmetic, correctly rounded either way),
// so the table holds the same bits without a division per call.
inline constexpr int kGammaTableSize = 64;
constexpr double gammaOf(int k) {
  const double ku = k * kUnitRoundoff;
  const double g = ku / (1.0 - ku);
  return g + g * 0x1p-51;  // up(g), g >= 0
}
inline constexpr std::array<double, kGammaTableSize> kGammaTable = [] {
  std::array<double, kGammaTableSize> table{};
  for (int k = 1; k < kGammaTableSize; ++k) table[k] = gammaOf(k);
  return table;
}();

}  // namespace region_detail

// gamma(k) = k u / (1 - k u), rounded up.
inline double gammaBound(int k) {
  if (k <= 0) return 0.0;
  if (k < region_detail::kGammaTableSize) return region_detail::kGammaTable[k];
  const double ku = k * kUnitRoundoff;
  const double g = ku / (1.0 - ku);
  return g + std::fabs(g) * 0x1p-51;
}

namespace region_detail {

// The bounds are sums of a few products of doubles: two double ULPs of
// margin per step keep them upper bounds of the real quantities. Every
// bound is at least 0, so the margin is one multiplication: for x = 0 or
// x >= 2^-971, x * 2^-51 is exact and x * (1 + 2^-51) rounds the same real
// number as x + |x| * 2^-51 does; below that it still rounds to at least x.
inline double up(double x) { return x * (1.0 + 0x1p-51); }

inline int nonNegative(int k) { return std::max(k, 0); }

// The sum of a product term's own rounding bounds (all of its
// multiplications), or of a sum's terms. A rounding before the product's
// last moves it by at most u of its value (the error is multiplied by the
// remaining factors); the last is under the float gap at its magnitude.
inline double termRoundingOf(const IntervalRegion& r) {
  if (r.kind == IntervalRegion::Kind::Sum) return r.termRounding;
  if (r.kind != IntervalRegion::Kind::Product) return 0.0;
  const int roundings = nonNegative(r.factors - 1 - r.exactFactors);
  if (roundings == 0) return 0.0;
  const double before = gammaBound(roundings - 1) * r.mag;
  return up(before + fp32_bits::gapAbove(up(r.mag + before)));
}

inline double termFlushOf(const IntervalRegion& r) {
  if (r.kind == IntervalRegion::Kind::Sum) return r.termFlush;
  if (r.kind == IntervalRegion::Kind::Product)
    return up(nonNegative(r.factors - 1 - r.exactFactors) * kFlushError * r.maxSub);
  return 0.0;
}

}  // namespace region_detail

// A closed value: its ideal magnitude and its error bound. `exactPowerOfTwo`
// for a literal +-2^n, which multiplies without rounding.
inline IntervalRegion leafRegion(double maxAbsIdeal, double err, bool exactPowerOfTwo) {
  IntervalRegion r;
  r.kind = IntervalRegion::Kind::Leaf;
  r.mag0 = maxAbsIdeal;
  r.mag = region_detail::up(maxAbsIdeal + err);
  r.maxSub = std::max(1.0, r.mag);
  r.exactFactors = exactPowerOfTwo ? 1 : 0;
  // An exact zero contributes no monomial: adding it rounds nothing.
  if (r.mag == 0.0) r.terms = 0;
  return r;
}

// The region of a + b (or a - b) and of a * b. Under the GLSL rules the
// caller closes a sum before it becomes a factor (no distributivity).
inline IntervalRegion sumRegion(const IntervalRegion& a, const IntervalRegion& b) {
  IntervalRegion r;
  r.kind = IntervalRegion::Kind::Sum;
  r.mag = region_detail::up(a.mag + b.mag);
  r.mag0 = a.mag0 + b.mag0;
  r.maxSub = std::max(a.maxSub, b.maxSub);
  r.terms = a.terms + b.terms;
  r.degree = std::max(a.degree, b.degree);
  r.termRounding =
      region_detail::up(region_detail::termRoundingOf(a) + region_detail::termRoundingOf(b));
  r.termFlush = region_detail::up(region_detail::termFlushOf(a) + region_detail::termFlushOf(b));
  return r;
}

inline IntervalRegion productRegion(const IntervalRegion& a, const IntervalRegion& b) {
  IntervalRegion r;
  r.kind = IntervalRegion::Kind::Product;
  r.mag = region_detail::up(a.mag * b.mag);
  r.mag0 = a.mag0 * b.mag0;
  r.maxSub = region_detail::up(a.maxSub * b.maxSub);
  r.terms = a.terms * b.terms;
  r.degree = a.degree + b.degree;
  r.factors = a.factors + b.factors;
  r.exactFactors = a.exactFactors + b.exactFactors;
  return r;
}

// Bound on |value before its last rounding - ideal| for every regrouping
// `rules` allow. A leaf has no pending rounding: its bound is its error.
inline double pendingError(const IntervalRegion& r, PrecisionRules rules) {
  const double propagated = std::max(0.0, r.mag - r.mag0);
  if (r.kind == IntervalRegion::Kind::Leaf) return propagated;
  if (rules == PrecisionRules::Vulkan) {
    // Every rounding of every equivalent formula relative to A.
    const int k = region_detail::nonNegative((r.degree - 1) + (std::max(r.terms, 1) - 1) - 1);
    return region_detail::up(gammaBound(k) * r.mag + propagated + k * kFlushError * r.maxSub);
  }
  if (r.kind == IntervalRegion::Kind::Product) {
    const int inexact = region_detail::nonNegative(r.factors - 1 - r.exactFactors);
    const int k = r.exactFactors > 0 ? inexact : region_detail::nonNegative(inexact - 1);
    return region_detail::up(gammaBound(k) * r.mag + propagated + k * kFlushError * r.maxSub);
  }
  // A sum of leaves and products: each term's own roundings, then the
  // sum's roundings before the last, each under the float gap at a partial
  // sum's magnitude (at most A plus the errors so far).
  const int k = region_detail::nonNegative(r.terms - 2);
  const double terms = r.termRounding + r.termFlush;
  const double partial =
      region_detail::up(region_detail::up(r.mag + terms) * (1.0 + gammaBound(k)));
  return region_detail::up(terms + k * (fp32_bits::gapAbove(partial) + kFlushError) + propagated);
}

// Whether some regrouping may overflow a partial result before the last
// operation (an overflowing last result is the float set's business).
inline bool mayOverflowInside(const IntervalRegion& r) {
  const int operations = (r.degree - 1) + (r.terms - 1);
  if (operations < 2) return false;
  return !(r.mag < kFp32Max * 0.5) || !(r.maxSub < kFp32Max * 0.5);
}

}  // namespace snell
