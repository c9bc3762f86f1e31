#include "adversary/adversarial_machine.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <utility>
#include <vector>

#include "oracle/fp32.h"
#include "oracle/interval_region.h"

namespace snell::adversary {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr double kDistributionTerms = kVulkanDistributionTerms;

struct Node {
  enum class Op : std::uint8_t { Leaf, Add, Mul, Neg };
  Op op = Op::Leaf;
  bool constant = false;
  bool hasMemo = false;
  int a = -1, b = -1;
  float value = 0.0f;   // Leaf
  float memo = 0.0f;    // the value computed once, when shared values are kept
  double folded = 0.0;  // a constant expression evaluated in double from its decimals
  double terms = 1.0;   // monomials in the full expansion
};

struct Factor {
  float value;
  bool constant;
  double folded;
};

struct Term {
  bool negative = false;
  std::vector<Factor> factors;
};

using Terms = std::vector<Term>;

// A value before its last rounding: a product x * y still open to be fused
// into the add that consumes it, or a float.
struct Pending {
  bool product = false;
  float x = 0.0f, y = 0.0f;
  float value = 0.0f;
};

struct State {
  std::vector<Node> nodes;
  std::uint64_t rng = 1;
  PrecisionRules rules = PrecisionRules::Glsl;
  Rounding rounding = Rounding::AnyNeighbour;
  int flushPercent = 0;       // chance that a denormal operand or result becomes 0
  int foldPercent = 0;        // chance that a constant expression is folded
  int fusePercent = 0;        // chance that a product is fused into its add
  int distributePercent = 0;  // Vulkan: chance that a product of sums is distributed
  bool keepShared = false;    // compute a shared subexpression once
};

thread_local State tState;

std::uint64_t next() {
  // splitmix64
  std::uint64_t z = (tState.rng += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

int below(int n) { return static_cast<int>(next() % static_cast<std::uint64_t>(n)); }
bool percent(int p) { return below(100) < p; }

// Floats in order as integers, for a uniform draw between two floats.
std::int64_t ordered(float f) {
  const auto bits = static_cast<std::int32_t>(std::bit_cast<std::uint32_t>(f));
  return bits < 0 ? -static_cast<std::int64_t>(bits & 0x7fffffff) : bits;
}
float fromOrdered(std::int64_t k) {
  const std::uint32_t bits =
      k < 0 ? (static_cast<std::uint32_t>(-k) | 0x80000000u) : static_cast<std::uint32_t>(k);
  return std::bit_cast<float>(bits);
}

// One of the floats in [lo, hi] (both floats, lo <= hi): an edge most often.
float pickBetween(float lo, float hi) {
  const int r = below(100);
  if (r < 35) return lo;
  if (r < 70) return hi;
  const std::int64_t a = ordered(lo), b = ordered(hi);
  return fromOrdered(a + static_cast<std::int64_t>(next() % static_cast<std::uint64_t>(b - a + 1)));
}

bool isDenormal(float f) { return f != 0.0f && std::fabs(f) < static_cast<float>(kFp32MinNormal); }

float maybeFlush(float f) {
  if (isDenormal(f) && percent(tState.flushPercent)) return std::copysign(0.0f, f);
  return f;
}

// Rounds the exact value hi + lo (a double-double, |lo| <= half a double
// ULP of hi) to a neighbouring float by the evaluation's policy.
float roundExact(double hi, double lo) {
  if (std::isnan(hi)) return kNaN;
  double down, up;
  if (std::isinf(hi)) {
    down = up = hi;
  } else if (isFloat(hi) && lo != 0.0) {
    const float f = static_cast<float>(hi);
    if (lo > 0.0) {
      down = f;
      up = std::nextafter(f, std::numeric_limits<float>::infinity());
    } else {
      up = f;
      down = std::nextafter(f, -std::numeric_limits<float>::infinity());
    }
  } else {
    down = floatAtOrBelow(hi);
    up = floatAtOrAbove(hi);
  }
  double r = down;
  switch (tState.rounding) {
    case Rounding::AnyNeighbour:
      r = percent(50) ? down : up;
      break;
    case Rounding::Nearest:
      r = (hi - down) + lo <= (up - hi) - lo ? down : up;
      break;
    case Rounding::TowardZero:
      r = hi > 0.0 || (hi == 0.0 && lo > 0.0) ? down : up;
      break;
    case Rounding::Up:
      r = up;
      break;
    case Rounding::Down:
      r = down;
      break;
  }
  return maybeFlush(static_cast<float>(r));
}

std::pair<double, double> twoSum(double a, double b) {
  const double s = a + b;
  if (!std::isfinite(s)) return {s, 0.0};
  const double bv = s - a;
  return {s, (a - (s - bv)) + (b - bv)};
}

float roundedProduct(float x, float y) {
  // A product of two floats is exact in double.
  return roundExact(static_cast<double>(maybeFlush(x)) * maybeFlush(y), 0.0);
}

float roundedSum(float x, float y) {
  const auto [s, e] = twoSum(maybeFlush(x), maybeFlush(y));
  return roundExact(s, e);
}

float fused(float x, float y, float c) {
  const auto [s, e] = twoSum(static_cast<double>(maybeFlush(x)) * maybeFlush(y), maybeFlush(c));
  return roundExact(s, e);
}

float settle(const Pending& p) { return p.product ? roundedProduct(p.x, p.y) : p.value; }

// A constant expression folded by the compiler: the double value rounded to
// either neighbouring float.
float foldToFloat(double folded) {
  if (!std::isfinite(folded)) return static_cast<float>(folded);
  const double down = floatAtOrBelow(folded), up = floatAtOrAbove(folded);
  return maybeFlush(static_cast<float>(percent(50) ? down : up));
}

// The Harrison ULP at x, the smaller where x's double approximation may sit
// on either side of a power of two.
double safeUlp(double x, double relative) {
  const double a = std::fabs(x);
  return std::min(ulp(a * (1.0 - relative)), ulp(a * (1.0 + relative)));
}

// A float within `ulps` ULP of the exact value, known as `approx` to within
// `relative` of itself.
float pickWithinUlps(double approx, double ulps, double relative) {
  if (std::isnan(approx)) return kNaN;
  const double margin = std::fabs(approx) * relative;
  const double radius = ulps * safeUlp(approx, relative) - margin;
  const double lo = approx - radius, hi = approx + radius;
  if (lo > kFp32Max) return percent(50) ? std::numeric_limits<float>::infinity() : kFp32Max;
  if (hi < -kFp32Max) return percent(50) ? -std::numeric_limits<float>::infinity() : -kFp32Max;
  const double flo = floatAtOrAbove(lo);
  double fhi = floatAtOrBelow(hi);
  if (hi > kFp32Max) fhi = percent(50) ? kInf : kFp32Max;
  if (std::isinf(fhi)) return maybeFlush(static_cast<float>(percent(50) ? flo : fhi));
  if (flo > fhi) return maybeFlush(static_cast<float>(floatAtOrBelow(approx)));
  return maybeFlush(pickBetween(static_cast<float>(flo), static_cast<float>(fhi)));
}

int add(Node n) {
  tState.nodes.push_back(n);
  return static_cast<int>(tState.nodes.size()) - 1;
}

Node nodeAt(int id) {
  if (id < 0) return Node{};
  return tState.nodes[static_cast<std::size_t>(id)];
}

Adv leaf(float value, bool constant = false, double folded = 0.0) {
  Node n;
  n.value = value;
  n.constant = constant;
  n.folded = folded;
  Adv r;
  r.node = add(n);
  return r;
}

float materialize(int id);
Terms expand(int id);

Term single(float value) { return Term{false, {Factor{value, false, 0.0}}}; }

// The terms of a sum of products over the tree's leaves.
Terms expand(int id) {
  const Node n = nodeAt(id);
  if (n.op == Node::Op::Leaf) return {Term{false, {Factor{n.value, n.constant, n.folded}}}};
  // A constant sum or product may be folded; a negation rounds nothing.
  if (n.constant && n.op != Node::Op::Neg && percent(tState.foldPercent)) {
    return {Term{false, {Factor{foldToFloat(n.folded), false, 0.0}}}};
  }
  if (n.hasMemo) return {single(n.memo)};
  switch (n.op) {
    case Node::Op::Neg: {
      Terms t = expand(n.a);
      for (Term& term : t) term.negative = !term.negative;
      return t;
    }
    case Node::Op::Add: {
      Terms t = expand(n.a);
      Terms u = expand(n.b);
      for (Term& term : u) t.push_back(std::move(term));
      return t;
    }
    case Node::Op::Mul:
    default: {
      Terms l = expand(n.a);
      Terms r = expand(n.b);
      // Within the oracle's budget, counted on the full expansion (as the
      // oracle counts, an exact zero aside), whatever was expanded here.
      const bool distribute = tState.rules == PrecisionRules::Vulkan &&
                              nodeAt(n.a).terms * nodeAt(n.b).terms <= kDistributionTerms &&
                              percent(tState.distributePercent);
      if (!distribute) {
        if (l.size() > 1) l = {single(materialize(n.a))};
        if (r.size() > 1) r = {single(materialize(n.b))};
      }
      Terms product;
      for (const Term& x : l)
        for (const Term& y : r) {
          Term t{x.negative != y.negative, x.factors};
          t.factors.insert(t.factors.end(), y.factors.begin(), y.factors.end());
          product.push_back(std::move(t));
        }
      return product;
    }
  }
}

// Folds the constant factors of a term into one, after regrouping them
// next to each other. That is the driver's folding, of the module's fp32
// constants (SPIR-V holds them as floats); glslang folds from the decimals,
// but only the expression as written (expand()).
void foldConstantFactors(Term& t) {
  std::vector<Factor> constants, others;
  for (const Factor& f : t.factors) (f.constant ? constants : others).push_back(f);
  if (constants.size() < 2 || !percent(tState.foldPercent)) return;
  double product = 1.0;
  for (const Factor& f : constants) product *= f.value;
  others.push_back(Factor{foldToFloat(product), false, 0.0});
  t.factors = std::move(others);
}

Pending termValue(Term& t) {
  foldConstantFactors(t);
  std::vector<float> pool;
  pool.reserve(t.factors.size());
  for (const Factor& f : t.factors) pool.push_back(f.value);
  if (t.negative) pool[0] = -pool[0];
  while (pool.size() > 2) {
    const auto i = static_cast<std::size_t>(below(static_cast<int>(pool.size())));
    std::swap(pool[i], pool.back());
    const float x = pool.back();
    pool.pop_back();
    const auto j = static_cast<std::size_t>(below(static_cast<int>(pool.size())));
    pool[j] = roundedProduct(pool[j], x);
  }
  if (pool.size() == 1) return Pending{false, 0.0f, 0.0f, pool[0]};
  return Pending{true, pool[0], pool[1], 0.0f};
}

Pending combine(const Pending& a, const Pending& b) {
  if (a.product && b.product) {
    if (percent(50)) return combine(Pending{false, 0, 0, settle(a)}, b);
    return combine(a, Pending{false, 0, 0, settle(b)});
  }
  if (a.product || b.product) {
    const Pending& p = a.product ? a : b;
    const Pending& c = a.product ? b : a;
    if (percent(tState.fusePercent)) return Pending{false, 0, 0, fused(p.x, p.y, c.value)};
    return Pending{false, 0, 0, roundedSum(settle(p), c.value)};
  }
  return Pending{false, 0, 0, roundedSum(a.value, b.value)};
}

float evaluate(Terms terms) {
  // Constant terms may be folded together once regrouped side by side (by
  // the driver, from their fp32 values, as foldConstantFactors).
  std::vector<std::size_t> constantTerms;
  for (std::size_t k = 0; k < terms.size(); ++k) {
    const bool constant = std::all_of(terms[k].factors.begin(), terms[k].factors.end(),
                                      [](const Factor& f) { return f.constant; });
    if (constant) constantTerms.push_back(k);
  }
  if (constantTerms.size() >= 2 && percent(tState.foldPercent)) {
    double sum = 0.0;
    for (std::size_t k : constantTerms) {
      double product = terms[k].negative ? -1.0 : 1.0;
      for (const Factor& f : terms[k].factors) product *= f.value;
      sum += product;
    }
    Terms kept;
    for (std::size_t k = 0; k < terms.size(); ++k)
      if (std::find(constantTerms.begin(), constantTerms.end(), k) == constantTerms.end())
        kept.push_back(std::move(terms[k]));
    kept.push_back(single(foldToFloat(sum)));
    terms = std::move(kept);
  }
  std::vector<Pending> pool;
  pool.reserve(terms.size());
  for (Term& t : terms) pool.push_back(termValue(t));
  while (pool.size() > 1) {
    const auto i = static_cast<std::size_t>(below(static_cast<int>(pool.size())));
    std::swap(pool[i], pool.back());
    const Pending x = pool.back();
    pool.pop_back();
    const auto j = static_cast<std::size_t>(below(static_cast<int>(pool.size())));
    pool[j] = combine(pool[j], x);
  }
  return settle(pool[0]);
}

float materialize(int id) {
  if (id < 0) return 0.0f;
  const Node n = nodeAt(id);
  if (n.op == Node::Op::Leaf) return n.value;
  if (n.hasMemo) return n.memo;
  const float value = evaluate(expand(id));
  if (tState.keepShared) {
    Node& stored = tState.nodes[static_cast<std::size_t>(id)];
    stored.hasMemo = true;
    stored.memo = value;
  }
  return value;
}

Adv binary(Node::Op op, const Adv& a, const Adv& b) {
  const Node na = nodeAt(a.node), nb = nodeAt(b.node);
  Node n;
  n.op = op;
  n.a = a.node < 0 ? leaf(0.0f, true, 0.0).node : a.node;
  n.b = b.node < 0 ? leaf(0.0f, true, 0.0).node : b.node;
  n.constant = (a.node < 0 || na.constant) && (b.node < 0 || nb.constant);
  const double fa = a.node < 0 ? 0.0 : na.folded, fb = b.node < 0 ? 0.0 : nb.folded;
  n.folded = op == Node::Op::Add ? fa + fb : fa * fb;
  const double ta = nodeAt(n.a).terms, tb = nodeAt(n.b).terms;
  n.terms = std::min(op == Node::Op::Add ? ta + tb : ta * tb, 1e9);
  Adv r;
  r.node = add(n);
  return r;
}

bool isConstant(const Adv& x) { return x.node >= 0 && nodeAt(x.node).constant; }
double foldedOf(const Adv& x) { return x.node < 0 ? 0.0 : nodeAt(x.node).folded; }

// A built-in of a constant argument may be folded: f in double, rounded
// to either neighbour. Returns false when not folded this time.
bool maybeFoldCall(const Adv& x, double (*f)(double), Adv& out) {
  if (!isConstant(x) || !percent(tState.foldPercent)) return false;
  const double value = f(foldedOf(x));
  if (!std::isfinite(value)) return false;
  out = leaf(foldToFloat(value), true, value);
  return true;
}

float quotient(float a, float b) {
  a = maybeFlush(a);
  b = maybeFlush(b);
  if (std::isnan(a) || std::isnan(b)) return kNaN;
  const double magnitude = std::fabs(static_cast<double>(b));
  if (magnitude < 0x1p-126 || magnitude > 0x1p126) return kNaN;  // the spec gives no bound
  const double q = static_cast<double>(a) / b;
  if (q == 0.0) return maybeFlush(0.0f);
  // a - q b exactly: the exact quotient is q + remainder / b.
  const double remainder = std::fma(-q, static_cast<double>(b), static_cast<double>(a));
  const double relative = std::fabs(remainder / b / q) + 0x1p-52;
  return pickWithinUlps(q, 2.5, relative);
}

// The libm double functions used as "exact" are within a few double ULPs.
constexpr double kLibmRelative = 0x1p-48;

// `x` as the argument arrives (a denormal may be flushed on the way in).
float inverseSqrtOf(float x, bool flushArgument = true) {
  if (flushArgument) x = maybeFlush(x);
  if (std::isnan(x) || x <= 0.0f) return kNaN;
  return pickWithinUlps(1.0 / std::sqrt(static_cast<double>(x)), 2.0, kLibmRelative);
}

// Vulkan bounds a built-in whose precision is inherited from a formula by
// [x - E, x + E] about the exact result x, E the largest distance of any of
// the formula's values: a value of the formula mirrored about x is within
// it. Half the calls under the Vulkan rules take the mirror.
bool mirrorsUnderVulkan() { return tState.rules == PrecisionRules::Vulkan && percent(50); }

// `formula` mirrored about `exact` (a libm value, within kLibmRelative of
// the exact result): the distance is shortened by that error twice and
// the mirror rounded toward the exact result, so that it is never farther
// from it than `formula` is.
float mirroredAbout(float formula, double exact) {
  if (!std::isfinite(formula) || !std::isfinite(exact)) return formula;
  // The subtraction's own rounding, where the formula is far from the
  // exact value, is taken off too.
  const double gap = std::fabs(formula - exact);
  const double distance = gap - 2.0 * std::fabs(exact) * kLibmRelative - gap * 0x1p-51;
  if (!(distance > 0.0)) return formula;
  return maybeFlush(static_cast<float>(formula > exact ? floatAtOrAbove(exact - distance)
                                                       : floatAtOrBelow(exact + distance)));
}

float log2Of(float x) {
  x = maybeFlush(x);
  if (std::isnan(x) || x <= 0.0f) return kNaN;
  const double exact = std::log2(static_cast<double>(x));
  if (x < 0.5f || x > 2.0f) return pickWithinUlps(exact, 3.0, kLibmRelative);
  // Absolute error strictly below 2^-21.
  const double margin = std::fabs(exact) * kLibmRelative + 0x1p-60;
  double lo = floatAtOrAbove(exact - 0x1p-21 + margin);
  double hi = floatAtOrBelow(exact + 0x1p-21 - margin);
  if (lo > hi) lo = hi = floatAtOrBelow(exact);
  return maybeFlush(pickBetween(static_cast<float>(lo), static_cast<float>(hi)));
}

float exp2Of(float x) {
  x = maybeFlush(x);
  if (std::isnan(x)) return kNaN;
  return pickWithinUlps(std::exp2(static_cast<double>(x)), 3.0 + 2.0 * std::fabs(x), kLibmRelative);
}

float expOf(float x) {
  x = maybeFlush(x);
  if (std::isnan(x)) return kNaN;
  return pickWithinUlps(std::exp(static_cast<double>(x)), 3.0 + 2.0 * std::fabs(x), kLibmRelative);
}

double doubleInverseSqrt(double x) { return 1.0 / std::sqrt(x); }
double doubleSqrt(double x) { return std::sqrt(x); }
double doubleExp2(double x) { return std::exp2(x); }
double doubleExp(double x) { return std::exp(x); }
double doubleLog2(double x) { return std::log2(x); }

}  // namespace

void Machine::begin(std::uint64_t seed, PrecisionRules rules) {
  tState.nodes.clear();
  tState.rng = seed;
  next();
  tState.rules = rules;
  tState.rounding = static_cast<Rounding>(below(5));
  if (below(3) == 0) tState.rounding = Rounding::AnyNeighbour;
  const int flushes[] = {0, 50, 100};
  tState.flushPercent = flushes[below(3)];
  const int folds[] = {0, 50, 100};
  tState.foldPercent = folds[below(3)];
  const int fuses[] = {0, 50, 100};
  tState.fusePercent = fuses[below(3)];
  const int distributes[] = {0, 50, 100};
  tState.distributePercent = distributes[below(3)];
  tState.keepShared = percent(50);
}

PrecisionRules Machine::rules() { return tState.rules; }
int Machine::choose(int n) { return below(n); }
std::size_t Machine::nodes() { return tState.nodes.size(); }

Adv::Adv(float value) { node = leaf(value).node; }

Adv Adv::literal(double decimal) { return leaf(nearestFloat(decimal), true, decimal); }

float Adv::value() const { return materialize(node); }

Adv operator+(const Adv& a, const Adv& b) { return binary(Node::Op::Add, a, b); }
Adv operator*(const Adv& a, const Adv& b) { return binary(Node::Op::Mul, a, b); }
Adv operator-(const Adv& a) {
  Node n;
  n.op = Node::Op::Neg;
  n.a = a.node < 0 ? leaf(0.0f, true, 0.0).node : a.node;
  const Node inner = nodeAt(n.a);
  n.constant = inner.constant;
  n.folded = -inner.folded;
  n.terms = inner.terms;
  Adv r;
  r.node = add(n);
  return r;
}
Adv operator-(const Adv& a, const Adv& b) { return a + (-b); }

Adv operator/(const Adv& a, const Adv& b) {
  if (isConstant(a) && isConstant(b) && percent(tState.foldPercent)) {
    const double value = foldedOf(a) / foldedOf(b);
    if (std::isfinite(value) && foldedOf(b) != 0.0) return leaf(foldToFloat(value), true, value);
  }
  const bool constant = isConstant(a) && isConstant(b);
  if (tState.rules == PrecisionRules::Vulkan && percent(50)) {
    // Vulkan's rearrangement by the properties of exact arithmetic: a / b
    // as a * (1 / b), the reciprocal within its 2.5 ULP, and the product
    // rounded once after the dividend is evaluated whole, or distributed
    // over the dividend's sum (x * (1 / b) + y * (1 / b)).
    const Adv reciprocal = leaf(quotient(1.0f, b.value()));
    if (isUndefined(reciprocal)) return leaf(kNaN);
    const Adv dividend = percent(50) ? a : leaf(a.value());
    return leaf((dividend * reciprocal).value(), constant, foldedOf(a) / foldedOf(b));
  }
  return leaf(quotient(a.value(), b.value()), constant, foldedOf(a) / foldedOf(b));
}

bool operator<(const Adv& a, const Adv& b) {
  const float x = maybeFlush(a.value()), y = maybeFlush(b.value());
  if (std::isnan(x) || std::isnan(y)) return percent(50);
  return x < y;
}

Adv inversesqrt(const Adv& x) {
  Adv r;
  if (maybeFoldCall(x, doubleInverseSqrt, r)) return r;
  return leaf(inverseSqrtOf(x.value()));
}

Adv sqrt(const Adv& x) {
  Adv r;
  if (maybeFoldCall(x, doubleSqrt, r)) return r;
  const float v = maybeFlush(x.value());
  if (std::isnan(v) || v < 0.0f) return leaf(kNaN);
  if (v == 0.0f) return leaf(0.0f);  // see the header: the formula's limit
  // Inherited from 1.0 / inversesqrt(x), x already past its one flush.
  const float formula = quotient(1.0f, inverseSqrtOf(v, false));
  if (mirrorsUnderVulkan()) return leaf(mirroredAbout(formula, std::sqrt(static_cast<double>(v))));
  return leaf(formula);
}

Adv exp2(const Adv& x) {
  Adv r;
  if (maybeFoldCall(x, doubleExp2, r)) return r;
  return leaf(exp2Of(x.value()));
}

Adv exp(const Adv& x) {
  Adv r;
  if (maybeFoldCall(x, doubleExp, r)) return r;
  return leaf(expOf(x.value()));
}

Adv log2(const Adv& x) {
  Adv r;
  if (maybeFoldCall(x, doubleLog2, r)) return r;
  return leaf(log2Of(x.value()));
}

// Inherited from exp2(y * log2(x)): log2 of x <= 0 is undefined, so is pow.
Adv pow(const Adv& x, const Adv& y) {
  if (isConstant(x) && isConstant(y) && percent(tState.foldPercent)) {
    const double value = std::exp2(foldedOf(y) * std::log2(foldedOf(x)));
    if (std::isfinite(value) && foldedOf(x) > 0.0) return leaf(foldToFloat(value), true, value);
  }
  if (mirrorsUnderVulkan()) {
    // The operands once, so that the mirror is about the exact result of
    // the values the formula took.
    const float base = x.value(), exponent = y.value();
    const float formula = exp2(Adv(exponent) * log2(Adv(base))).value();
    return leaf(
        mirroredAbout(formula, std::pow(static_cast<double>(base), static_cast<double>(exponent))));
  }
  return exp2(y * log2(x));
}

Adv max(const Adv& a, const Adv& b) {
  const float x = maybeFlush(a.value()), y = maybeFlush(b.value());
  if (std::isnan(x) || std::isnan(y)) return leaf(kNaN);
  return leaf(y > x ? y : x);
}

Adv min(const Adv& a, const Adv& b) {
  const float x = maybeFlush(a.value()), y = maybeFlush(b.value());
  if (std::isnan(x) || std::isnan(y)) return leaf(kNaN);
  return leaf(y < x ? y : x);
}

Adv abs(const Adv& x) { return leaf(std::fabs(maybeFlush(x.value()))); }

Adv sumOfProducts(std::span<const Adv> a, std::span<const Adv> b) {
  Adv sum = a[0] * b[0];
  for (std::size_t i = 1; i < a.size(); ++i) sum = sum + a[i] * b[i];
  return sum;
}

bool isUndefined(const Adv& x) { return std::isnan(x.value()); }

}  // namespace snell::adversary
