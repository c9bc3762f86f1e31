#include "oracle/interval.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

#include "oracle/fp32_bits.h"
#include "oracle/interval_float_sets.h"
#include "oracle/interval_region_bounds.h"

namespace snell {
namespace {

using float_sets::Range;

constexpr double kInf = std::numeric_limits<double>::infinity();

double maxAbs(double lo, double hi) { return std::max(std::fabs(lo), std::fabs(hi)); }

bool sameBits(double a, double b) { return fp32_bits::bitsOf(a) == fp32_bits::bitsOf(b); }

bool isExactPowerOfTwo(double x) { return fp32_bits::isPositivePowerOfTwo(std::fabs(x)); }

// Whether `v` is a literal +-2^n, given the error it has when closed.
bool exactPowerOfTwoLiteral(const Interval& v, double err) {
  return v.constant && v.lo == v.hi && err == 0.0 && isExactPowerOfTwo(v.lo);
}

// The region of a closed value: a leaf with its error.
IntervalRegion closedRegion(const Interval& v) {
  return leafRegion(maxAbs(v.idealLo, v.idealHi), v.err, exactPowerOfTwoLiteral(v, v.err));
}

// What closedView(v) changes, without copying the rest of v: its ideal
// range and error (under the GLSL rules a float set narrower than the ideal
// range widened by the error stands for the value, exactly), and its region.
struct ClosedParts {
  double idealLo;
  double idealHi;
  double err;
  IntervalRegion region;
};

ClosedParts closedParts(const Interval& v, PrecisionRules rules) {
  const bool setIsTighter = rules == PrecisionRules::Glsl && std::isfinite(v.lo) &&
                            std::isfinite(v.hi) &&
                            v.hi - v.lo <= (v.idealHi - v.idealLo) + 2.0 * v.err;
  ClosedParts parts{v.idealLo, v.idealHi, v.err, {}};
  if (setIsTighter) {
    parts.idealLo = v.lo;
    parts.idealHi = v.hi;
    parts.err = 0.0;
  }
  parts.region = leafRegion(maxAbs(parts.idealLo, parts.idealHi), parts.err,
                            exactPowerOfTwoLiteral(v, parts.err));
  return parts;
}

// A constant expression's result may also be the compiler's own folding of
// the decimal literals, rounded once to fp32 (either way: a double
// evaluation is within a few double ULPs of exact, well inside the float
// gap): both neighbouring floats of the double value, whichever the
// compiler's rounding picks. The allowed set and the error bound grow to
// hold them too;
// the region keeps the fold as an alternative leaf.
void addFold(Interval& r, double folded) {
  if (r.undefined || !std::isfinite(folded)) return;
  const double slop = std::fabs(folded) * 0x1p-50;
  const Range fold =
      float_sets::admitFlushToZero(float_sets::roundedAround({folded, folded}, slop));
  r.lo = std::min(r.lo, fold.lo);
  r.hi = std::max(r.hi, fold.hi);
  const double foldErr = std::max(std::fabs(fold.hi - r.idealLo), std::fabs(r.idealHi - fold.lo));
  r.err = std::max(r.err, foldErr);
  r.region.mag = std::max(r.region.mag, r.region.mag0 + foldErr);
  r.region.maxSub = std::max(r.region.maxSub, r.region.mag);
  r.constant = true;
  r.folded = folded;
}

// Bounds past the float range: a result there may be the largest float or
// an infinity, so its distance from the ideal value has no bound.
double errUnlessOverflowed(double idealLo, double idealHi, double err) {
  return maxAbs(idealLo, idealHi) + err > kFp32Max ? kInf : err;
}

// An operation's result from its float set (0 already admitted where a
// flush may give it), its ideal range and the bound on its error before
// its last rounding.
void writeResult(Interval& r, Range set, Range ideal, double pending) {
  r.lo = set.lo;
  r.hi = set.hi;
  r.idealLo = ideal.lo;
  r.idealHi = ideal.hi;
  r.err = errUnlessOverflowed(
      ideal.lo, ideal.hi,
      pending + float_sets::roundingError(ideal.lo - pending, ideal.hi + pending));
}

enum class RegionOp { Add, Multiply };

// a + b or a * b: the ideal range, the region of every regrouping with the
// operands' own open regions, and the floats that can come out of it.
// Written into `r`, a default Interval that is neither operand: the callers
// return it by name, so it is built in place instead of copied out whole.
// One instance per operation, inlined into its operator (which is
// flattened: GCC at -O2 kept closedParts, exactProductRange, pendingError
// and roundedAround as calls, a tenth of an operation's instructions).
template <RegionOp op>
[[gnu::always_inline]] inline void combineInto(Interval& r, const Interval& a, const Interval& b) {
  if (a.undefined || b.undefined || !std::isfinite(a.err) || !std::isfinite(b.err)) {
    r = Interval::unconstrained();
    return;
  }
  const PrecisionRules rules = currentPrecisionRules();
  // An open region joins the result's region; without distributivity a
  // sum is rounded before it is multiplied, and a leaf is taken closed.
  // Under Vulkan a product past the distribution budget takes its
  // operands of several terms closed.
  const bool overBudget =
      op == RegionOp::Multiply && rules == PrecisionRules::Vulkan &&
      static_cast<double>(a.region.terms) * b.region.terms > kVulkanDistributionTerms;
  const auto isOpen = [&](const Interval& v) {
    return v.region.kind != IntervalRegion::Kind::Leaf &&
           !(op == RegionOp::Multiply && rules == PrecisionRules::Glsl &&
             v.region.kind == IntervalRegion::Kind::Sum) &&
           !(overBudget && v.region.terms > 1);
  };
  // The operands' ideal ranges and regions, open or closed (closedView).
  const auto parts = [&](const Interval& v) {
    return isOpen(v) ? ClosedParts{v.idealLo, v.idealHi, v.err, v.region} : closedParts(v, rules);
  };
  const ClosedParts av = parts(a);
  const ClosedParts bv = parts(b);
  const IntervalRegion& ra = av.region;
  const IntervalRegion& rb = bv.region;
  r.region = op == RegionOp::Add ? sumRegion(ra, rb) : productRegion(ra, rb);
  if (mayOverflowInside(r.region)) {
    r = Interval::unconstrained();
    return;
  }
  const Range ideal =
      op == RegionOp::Add
          ? float_sets::exactSumRange(av.idealLo, av.idealHi, bv.idealLo, bv.idealHi)
          : float_sets::exactProductRange(av.idealLo, av.idealHi, bv.idealLo, bv.idealHi);
  const double pending = pendingError(r.region, rules);
  Range set = float_sets::roundedAround(ideal, pending);
  // A single operation on closed operands has one order only: the plain
  // interval of it is exact and holds as well.
  if (ra.kind == IntervalRegion::Kind::Leaf && rb.kind == IntervalRegion::Kind::Leaf) {
    // Where the operands' float sets are their ideal ranges (inputs, and
    // closed values whose set is the tighter bound), the exact range of the
    // plain interval is `ideal` itself: rounded out, not computed again.
    const bool setsAreIdeal = sameBits(a.lo, av.idealLo) && sameBits(a.hi, av.idealHi) &&
                              sameBits(b.lo, bv.idealLo) && sameBits(b.hi, bv.idealHi) &&
                              !std::isnan(ideal.lo) && !std::isnan(ideal.hi);
    const Range plain = setsAreIdeal          ? Range{fp32_bits::floatAtOrBelow(ideal.lo),
                                             fp32_bits::floatAtOrAbove(ideal.hi)}
                        : op == RegionOp::Add ? float_sets::roundedSum(a.lo, a.hi, b.lo, b.hi)
                                              : float_sets::roundedProduct(a.lo, a.hi, b.lo, b.hi);
    set.lo = std::max(set.lo, plain.lo);
    set.hi = std::min(set.hi, plain.hi);
  }
  if (std::isnan(set.lo) || std::isnan(set.hi) || set.lo > set.hi) {
    r = Interval::unconstrained();
    return;
  }
  writeResult(r, float_sets::admitFlushToZero(set), ideal, pending);
  if (a.constant && b.constant)
    addFold(r, op == RegionOp::Add ? a.folded + b.folded : a.folded * b.folded);
}

// A float as it is, exactly: a leaf with no error whose set and ideal range
// are one finite float (an input or a uniform, not a literal). closedParts
// gives such a value's own bounds and a fresh leaf region, under either
// rules.
bool isExactPoint(const Interval& v) {
  const std::uint64_t bits = fp32_bits::bitsOf(v.lo);
  return v.region.kind == IntervalRegion::Kind::Leaf && !v.undefined && !v.constant &&
         v.err == 0.0 && bits == fp32_bits::bitsOf(v.hi) && bits == fp32_bits::bitsOf(v.idealLo) &&
         bits == fp32_bits::bitsOf(v.idealHi) && std::fabs(v.lo) <= kFp32Max;
}

// combineInto's product for two exact points, the same bits by a shorter
// road. Of its steps: one exact product; no overflow inside (one
// operation); and the set is the plain interval, because pending >= 0 puts
// the set rounded around the ideal value at or outside the plain one, and
// their intersection is the plain one's bounds themselves. Checked against
// the general road (IntervalShortcut.APointProductTakesTheGeneralRoadsBits).
void exactPointProductInto(Interval& r, const Interval& a, const Interval& b) {
  const double x = a.lo;
  const double y = b.lo;
  r.region =
      productRegion(leafRegion(std::fabs(x), 0.0, false), leafRegion(std::fabs(y), 0.0, false));
  const Range ideal = float_sets::exactProductRange(x, x, y, y);
  const double pending = pendingError(r.region, currentPrecisionRules());
  writeResult(r,
              float_sets::admitFlushToZero(
                  {fp32_bits::floatAtOrBelow(ideal.lo), fp32_bits::floatAtOrAbove(ideal.hi)}),
              ideal, pending);
}

}  // namespace

Interval::Interval(double low, double high)
    : lo(low),
      hi(high),
      idealLo(low),
      idealHi(high),
      region(leafRegion(maxAbs(low, high), 0.0, false)) {}

// Flattened: an input's Interval is made for every component of every
// call, and GCC at -O2 kept the constructor as a call.
[[gnu::flatten]] Interval Interval::point(float value) {
  if (std::isnan(value)) return unconstrained();
  Interval r(value, value);
  if (std::fabs(value) < kFp32MinNormal && value != 0.0f) {
    // A denormal input may arrive flushed to 0.
    const Range set = float_sets::admitFlushToZero({r.lo, r.hi});
    r.lo = set.lo;
    r.hi = set.hi;
    r.err = std::fabs(static_cast<double>(value));
    r.region = leafRegion(r.err, r.err, false);
  }
  return r;
}

namespace {

// A decimal read into a double first and then rounded to float may round
// the other way from the decimal rounded to float at once: only where the
// double is exactly halfway between two floats. Which of them the decimal
// was nearer is lost, and a driver's compiler may parse either way: both.
bool isFloatMidpoint(double decimal) {
  const double below = fp32_bits::floatAtOrBelow(decimal);
  const double above = fp32_bits::floatAtOrAbove(decimal);
  return below != above && std::isfinite(below) && std::isfinite(above) &&
         below + above == 2.0 * decimal;
}

Interval makeLiteral(double decimal) {
  Interval r = Interval::point(nearestFloat(decimal));
  if (r.undefined) return r;
  if (isFloatMidpoint(decimal)) {
    const Range both = float_sets::admitFlushToZero(
        {fp32_bits::floatAtOrBelow(decimal), fp32_bits::floatAtOrAbove(decimal)});
    r = Interval(both.lo, both.hi);
  }
  r.constant = true;
  r.folded = decimal;
  r.region = closedRegion(r);
  return r;
}

// A listing uses a handful of literals, each on every evaluation (refract's
// 0.0 and 1.0 four times a call): the last few made on this thread are
// kept, keyed by the decimal's bits (0.0 and -0.0 apart).
struct LiteralMemo {
  static constexpr std::size_t kSize = 8;
  std::array<std::uint64_t, kSize> keys{};
  std::array<Interval, kSize> values{};
  std::size_t filled = 0;
  std::size_t next = 0;
};
thread_local LiteralMemo tLiterals;

}  // namespace

Interval Interval::literal(double decimal) {
  const std::uint64_t key = fp32_bits::bitsOf(decimal);
  LiteralMemo& memo = tLiterals;
  for (std::size_t k = 0; k < memo.filled; ++k)
    if (memo.keys[k] == key) return memo.values[k];
  const Interval r = makeLiteral(decimal);
  memo.keys[memo.next] = key;
  memo.values[memo.next] = r;
  memo.filled = std::max(memo.filled, memo.next + 1);
  memo.next = (memo.next + 1) % LiteralMemo::kSize;
  return r;
}

Interval Interval::unconstrained() {
  Interval r(-kInf, kInf);
  r.undefined = true;
  r.err = kInf;
  return r;
}

[[gnu::flatten]] Interval operator+(const Interval& a, const Interval& b) {
  Interval r;
  combineInto<RegionOp::Add>(r, a, b);
  return r;
}

Interval operator-(const Interval& a) {
  Interval r = a;
  r.lo = -a.hi;
  r.hi = -a.lo;
  r.idealLo = -a.idealHi;
  r.idealHi = -a.idealLo;
  r.folded = -a.folded;
  return r;
}

// Flattened: refract subtracts four times a call, and the negation and the
// sum were two calls.
[[gnu::flatten]] Interval operator-(const Interval& a, const Interval& b) { return a + (-b); }

[[gnu::flatten]] Interval operator*(const Interval& a, const Interval& b) {
  Interval r;
  if (isExactPoint(a) && isExactPoint(b))
    exactPointProductInto(r, a, b);
  else
    combineInto<RegionOp::Multiply>(r, a, b);
  return r;
}

namespace {

Interval divided(const Interval& aIn, const Interval& bIn);

}  // namespace

// Under Vulkan a / b may also be a * (1 / b) with the product distributed
// over the dividend ("Evaluation of Expressions" allows any property of
// exact arithmetic): (x + y) / c as x * (1 / c) + y * (1 / c), the
// reciprocal within its 2.5 ULP. The quotient stays closed to its
// consumer: a rearrangement across the division, such as a * (b / c) as
// (a * b) / c, is not modelled (README, "Soundness").
Interval operator/(const Interval& aIn, const Interval& bIn) {
  const Interval direct = divided(aIn, bIn);
  if (direct.undefined || currentPrecisionRules() != PrecisionRules::Vulkan) return direct;
  // A dividend of exactly 1 (sqrt's 1.0 / inversesqrt(x)) is the
  // reciprocal's own: the quotient is the reciprocal, bit for bit, unless a
  // constant divisor would fold with the literal.
  const bool dividendIsOne = aIn.lo == 1.0 && aIn.hi == 1.0 && aIn.idealLo == 1.0 &&
                             aIn.idealHi == 1.0 && aIn.err == 0.0 && !bIn.constant;
  const Interval reciprocal = dividendIsOne ? direct : divided(Interval::literal(1.0), bIn);
  Interval r = withAlternative(direct, aIn * reciprocal);
  if (!r.undefined && aIn.constant && bIn.constant) addFold(r, aIn.folded / bIn.folded);
  return r;
}

namespace {

Interval divided(const Interval& aIn, const Interval& bIn) {
  if (aIn.undefined || bIn.undefined) return Interval::unconstrained();
  const Interval a = closedView(aIn);
  const Interval b = closedView(bIn);
  if (b.lo <= 0.0 && b.hi >= 0.0) return Interval::unconstrained();
  const double smallest = std::min(std::fabs(b.lo), std::fabs(b.hi));
  const double largest = maxAbs(b.lo, b.hi);
  if (smallest < 0x1p-126 || largest > 0x1p126) return Interval::unconstrained();
  if (b.idealLo <= 0.0 && b.idealHi >= 0.0) return Interval::unconstrained();
  const Range quotients = float_sets::quotientRange(a.lo, a.hi, b.lo, b.hi);
  Range set = float_sets::withinUlps(quotients.lo, quotients.hi, 2.5);
  // Where the operands' float sets are their ideal ranges (inputs, and
  // closed values whose set is the tighter bound) the exact quotients are
  // those already made.
  const bool setsAreIdeal = sameBits(a.lo, a.idealLo) && sameBits(a.hi, a.idealHi) &&
                            sameBits(b.lo, b.idealLo) && sameBits(b.hi, b.idealHi);
  const Range ideal = setsAreIdeal
                          ? quotients
                          : float_sets::quotientRange(a.idealLo, a.idealHi, b.idealLo, b.idealHi);
  // |a'/b' - a/b| <= (|a' - a| |b| + |a| |b' - b|) / (|b'| |b|), then the
  // 2.5 ULP of the division itself at the computed quotient.
  const double idealSmallest = std::min(std::fabs(b.idealLo), std::fabs(b.idealHi));
  const double propagated =
      (a.err * maxAbs(b.idealLo, b.idealHi) + maxAbs(a.idealLo, a.idealHi) * b.err) /
      (smallest * idealSmallest);
  double own = 2.5 * fp32_bits::gapAbove(maxAbs(quotients.lo, quotients.hi)) +
               float_sets::flushError(quotients.lo, quotients.hi);
  if (currentPrecisionRules() == PrecisionRules::Vulkan) {
    // Vulkan lets an implementation rearrange by any property of exact
    // arithmetic ("Evaluation of Expressions"): a / b as a * (1 / b), the
    // reciprocal within its 2.5 ULP, then one rounding of the product. Its
    // own error: |a'| times the reciprocal's, then the product's rounding.
    // With a dividend of exactly 1 the reciprocal is the quotient itself.
    const bool dividendIsOne = sameBits(a.lo, 1.0) && sameBits(a.hi, 1.0);
    const Range reciprocals =
        dividendIsOne ? quotients : float_sets::quotientRange(1.0, 1.0, b.lo, b.hi);
    const Range reciprocal =
        dividendIsOne ? set : float_sets::withinUlps(reciprocals.lo, reciprocals.hi, 2.5);
    const Range products = float_sets::roundedProduct(a.lo, a.hi, reciprocal.lo, reciprocal.hi);
    if (std::isnan(products.lo) || std::isnan(products.hi)) return Interval::unconstrained();
    set.lo = std::min(set.lo, products.lo);
    set.hi = std::max(set.hi, products.hi);
    const double viaReciprocal =
        maxAbs(a.lo, a.hi) * (2.5 * fp32_bits::gapAbove(maxAbs(reciprocals.lo, reciprocals.hi)) +
                              float_sets::flushError(reciprocal.lo, reciprocal.hi)) +
        float_sets::roundingError(products.lo, products.hi);
    own = std::max(own, float_sets::up(viaReciprocal));
  }
  Interval r = leafValue(set.lo, set.hi, ideal.lo, ideal.hi, float_sets::up(propagated + own));
  if (aIn.constant && bIn.constant) addFold(r, aIn.folded / bIn.folded);
  return r;
}

}  // namespace

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
  return leafValue(std::min(a.lo, b.lo), std::max(a.hi, b.hi), std::min(a.idealLo, b.idealLo),
                   std::max(a.idealHi, b.idealHi), std::max(a.err, b.err));
}

Interval withinUlps(double exactLo, double exactHi, double ulps) {
  if (std::isnan(exactLo) || std::isnan(exactHi)) return Interval::unconstrained();
  const Range set = float_sets::withinUlps(exactLo, exactHi, ulps);
  return Interval(set.lo, set.hi);
}

Interval withinDistance(double exactLo, double exactHi, double distance) {
  if (std::isnan(exactLo) || std::isnan(exactHi)) return Interval::unconstrained();
  const Range set = float_sets::strictlyWithin(exactLo - distance, exactHi + distance);
  return Interval(set.lo, set.hi);
}

Interval leafValue(double lo, double hi, double idealLo, double idealHi, double err) {
  if (!std::isfinite(err) || std::isnan(lo) || std::isnan(hi) || std::isnan(idealLo) ||
      std::isnan(idealHi))
    return Interval::unconstrained();
  const Range set = float_sets::admitFlushToZero({lo, hi});
  Interval r(set.lo, set.hi);
  r.idealLo = idealLo;
  r.idealHi = idealHi;
  r.err = errUnlessOverflowed(idealLo, idealHi, err);
  r.region = closedRegion(r);
  return r;
}

Interval closedView(const Interval& value) {
  if (value.undefined) return value;
  const ClosedParts parts = closedParts(value, currentPrecisionRules());
  Interval r = value;
  r.idealLo = parts.idealLo;
  r.idealHi = parts.idealHi;
  r.err = parts.err;
  r.region = parts.region;
  return r;
}

Interval withAlternative(const Interval& value, const Interval& alternative) {
  if (value.undefined || alternative.undefined) return Interval::unconstrained();
  Interval r = value;
  r.lo = std::min(value.lo, alternative.lo);
  r.hi = std::max(value.hi, alternative.hi);
  r.idealLo = std::min(value.idealLo, alternative.idealLo);
  r.idealHi = std::max(value.idealHi, alternative.idealHi);
  // The alternative's distance from the exact value: its own error, and
  // the gap between the two ideal ranges (the same function, bounded
  // two ways).
  const double spread = std::max(std::fabs(alternative.idealLo - r.idealLo),
                                 std::fabs(r.idealHi - alternative.idealHi));
  const double altErr = float_sets::up(alternative.err + spread);
  r.err = std::max(r.err, altErr);
  r.region.mag = std::max(r.region.mag, float_sets::up(r.region.mag0 + altErr));
  r.region.maxSub = std::max(r.region.maxSub, r.region.mag);
  r.constant = false;
  return r;
}

Interval symmetricAboutIdeal(const Interval& value) {
  if (value.undefined) return value;
  Interval r = value;
  if (!std::isfinite(value.err)) {
    // A value of the formula may be past the float range (an infinity): E
    // has no bound, and neither has [x - E, x + E].
    r.lo = -kInf;
    r.hi = kInf;
    return r;
  }
  const Range symmetric =
      float_sets::floatsIn(value.idealLo - value.err, value.idealHi + value.err);
  r.lo = std::min(r.lo, symmetric.lo);
  r.hi = std::max(r.hi, symmetric.hi);
  return r;
}

}  // namespace snell
