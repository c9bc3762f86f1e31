#include "oracle/interval_region.h"

#include <algorithm>
#include <cmath>

#include "oracle/fp32_bits.h"

namespace snell {
namespace {

// The bounds are sums of a few products of doubles: two double ULPs of
// margin per step keep them upper bounds of the real quantities.
double up(double x) { return x + std::fabs(x) * 0x1p-51; }

int nonNegative(int k) { return std::max(k, 0); }

// The sum of a product term's own rounding bounds (all of its
// multiplications), or of a sum's terms. A rounding before the product's
// last moves it by at most u of its value (the error is multiplied by the
// remaining factors); the last is under the float gap at its magnitude.
double termRoundingOf(const IntervalRegion& r) {
  if (r.kind == IntervalRegion::Kind::Sum) return r.termRounding;
  if (r.kind != IntervalRegion::Kind::Product) return 0.0;
  const int roundings = nonNegative(r.factors - 1 - r.exactFactors);
  if (roundings == 0) return 0.0;
  const double before = gammaBound(roundings - 1) * r.mag;
  return up(before + fp32_bits::gapAbove(up(r.mag + before)));
}

double termFlushOf(const IntervalRegion& r) {
  if (r.kind == IntervalRegion::Kind::Sum) return r.termFlush;
  if (r.kind == IntervalRegion::Kind::Product)
    return up(nonNegative(r.factors - 1 - r.exactFactors) * kFlushError * r.maxSub);
  return 0.0;
}

}  // namespace

double gammaBound(int k) {
  if (k <= 0) return 0.0;
  const double ku = k * kUnitRoundoff;
  return up(ku / (1.0 - ku));
}

IntervalRegion leafRegion(double maxAbsIdeal, double err, bool exactPowerOfTwo) {
  IntervalRegion r;
  r.kind = IntervalRegion::Kind::Leaf;
  r.mag0 = maxAbsIdeal;
  r.mag = up(maxAbsIdeal + err);
  r.maxSub = std::max(1.0, r.mag);
  r.exactFactors = exactPowerOfTwo ? 1 : 0;
  // An exact zero contributes no monomial: adding it rounds nothing.
  if (r.mag == 0.0) r.terms = 0;
  return r;
}

IntervalRegion sumRegion(const IntervalRegion& a, const IntervalRegion& b) {
  IntervalRegion r;
  r.kind = IntervalRegion::Kind::Sum;
  r.mag = up(a.mag + b.mag);
  r.mag0 = a.mag0 + b.mag0;
  r.maxSub = std::max(a.maxSub, b.maxSub);
  r.terms = a.terms + b.terms;
  r.degree = std::max(a.degree, b.degree);
  r.termRounding = up(termRoundingOf(a) + termRoundingOf(b));
  r.termFlush = up(termFlushOf(a) + termFlushOf(b));
  return r;
}

IntervalRegion productRegion(const IntervalRegion& a, const IntervalRegion& b) {
  IntervalRegion r;
  r.kind = IntervalRegion::Kind::Product;
  r.mag = up(a.mag * b.mag);
  r.mag0 = a.mag0 * b.mag0;
  r.maxSub = up(a.maxSub * b.maxSub);
  r.terms = a.terms * b.terms;
  r.degree = a.degree + b.degree;
  r.factors = a.factors + b.factors;
  r.exactFactors = a.exactFactors + b.exactFactors;
  return r;
}

double pendingError(const IntervalRegion& r, PrecisionRules rules) {
  const double propagated = std::max(0.0, r.mag - r.mag0);
  if (r.kind == IntervalRegion::Kind::Leaf) return propagated;
  if (rules == PrecisionRules::Vulkan) {
    // Every rounding of every equivalent formula relative to A.
    const int k = nonNegative((r.degree - 1) + (std::max(r.terms, 1) - 1) - 1);
    return up(gammaBound(k) * r.mag + propagated + k * kFlushError * r.maxSub);
  }
  if (r.kind == IntervalRegion::Kind::Product) {
    const int inexact = nonNegative(r.factors - 1 - r.exactFactors);
    const int k = r.exactFactors > 0 ? inexact : nonNegative(inexact - 1);
    return up(gammaBound(k) * r.mag + propagated + k * kFlushError * r.maxSub);
  }
  // A sum of leaves and products: each term's own roundings, then the
  // sum's roundings before the last, each under the float gap at a partial
  // sum's magnitude (at most A plus the errors so far).
  const int k = nonNegative(r.terms - 2);
  const double terms = r.termRounding + r.termFlush;
  const double partial = up(up(r.mag + terms) * (1.0 + gammaBound(k)));
  return up(terms + k * (fp32_bits::gapAbove(partial) + kFlushError) + propagated);
}

bool mayOverflowInside(const IntervalRegion& r) {
  const int operations = (r.degree - 1) + (r.terms - 1);
  if (operations < 2) return false;
  return !(r.mag < kFp32Max * 0.5) || !(r.maxSub < kFp32Max * 0.5);
}

}  // namespace snell
