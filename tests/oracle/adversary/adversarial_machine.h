#pragma once
// The adversarial conforming machine: a software fp32 implementation that,
// at random, makes every choice the GLSL 4.60 (section 4.7.1, 4.9) and
// Vulkan ("Precision and Operation of SPIR-V Instructions") rules allow, so
// that the oracle's intervals can be held against what a conforming GPU may
// really return.
//
// Adv is a number type for the listing templates (oracle/glsl). + - * build
// an expression tree instead of computing; the tree is evaluated where an
// implementation has to produce a value: a built-in's argument, a division,
// a comparison, an output. There the machine
// - expands the tree into a sum of products (GLSL: a sum that is a factor is
//   evaluated first; Vulkan: it may also be distributed), so that every
//   regrouping of products of 3+ factors and of sums, constants included, is
//   reachable (no listing marks anything `precise`);
// - multiplies and adds in a random tree shape and order, fuses any product
//   into the add that consumes it (a*b+c rounded once);
// - rounds each result to either neighbouring float, by a policy drawn per
//   evaluation: a random neighbour per operation, or to nearest, toward
//   zero, up or down throughout;
// - may flush any denormal operand or result to zero;
// - may fold a constant expression (literals and `const` values only) in
//   double from the decimals as written and round it to either neighbour;
// - returns transcendentals, inversesqrt and division anywhere inside their
//   ULP bound, preferring the two edges;
// - under the Vulkan rules, may return sqrt and pow (whose precision is
//   inherited from a formula) mirrored about the exact result, as the
//   rule's [x - E, x + E] allows;
// - under the Vulkan rules, may divide as a * (1 / b), distributed over the
//   dividend's sum or not;
// - may re-evaluate a shared subexpression at each use, or compute it once.
//
// A value the spec leaves undefined (log2 or inversesqrt of x <= 0, sqrt of
// x < 0, a divisor outside [2^-126, 2^126], pow by way of log2(0), an
// overflow) is NaN: the oracle must then call the component undefined.
//
// sqrt(0) is 0. GLSL defines sqrt's result as undefined only for x < 0, and
// its precision is inherited from 1.0 / inversesqrt(x); at x = 0 that
// formula's limit 1 / inf is 0, which every implementation returns. Taking
// it as defined is what lets a near-critical refract() read-back that mixes
// the zero vector with the refracted ray be rejected.
#include <cstdint>
#include <span>

#include "oracle/glsl/scalar.h"
#include "oracle/precision_rules.h"

namespace snell::adversary {

// Per-evaluation policies, drawn by Machine::begin.
enum class Rounding : std::uint8_t { AnyNeighbour, Nearest, TowardZero, Up, Down };

// The machine's state for one evaluation, on this thread.
class Machine {
 public:
  // Starts an evaluation: clears the expression store, seeds the choices and
  // draws the per-evaluation policies.
  static void begin(std::uint64_t seed, PrecisionRules rules);
  static PrecisionRules rules();
  // A uniform draw in [0, n).
  static int choose(int n);
  // Nodes created so far (for the evaluation count's cost accounting).
  static std::size_t nodes();
};

class Adv {
 public:
  Adv() = default;  // 0.0
  explicit Adv(float value);
  // A literal or `const float` as printed.
  static Adv literal(double decimal);
  // For a built-in with several legal formulas: which one this run uses.
  static int chooseFormula(int n) { return Machine::choose(n); }

  // The fp32 value an implementation returns (NaN where the spec leaves it
  // undefined). Evaluates the tree with fresh choices.
  float value() const;

  int node = -1;  // into the thread's store; -1 is an exact 0
};

Adv operator+(const Adv& a, const Adv& b);
Adv operator-(const Adv& a, const Adv& b);
Adv operator*(const Adv& a, const Adv& b);
Adv operator-(const Adv& a);
Adv operator/(const Adv& a, const Adv& b);
// An undefined operand makes either outcome possible.
bool operator<(const Adv& a, const Adv& b);

Adv inversesqrt(const Adv& x);
Adv sqrt(const Adv& x);
Adv exp2(const Adv& x);
Adv exp(const Adv& x);
Adv log2(const Adv& x);
Adv pow(const Adv& x, const Adv& y);
Adv max(const Adv& a, const Adv& b);
Adv min(const Adv& a, const Adv& b);
Adv abs(const Adv& x);
// dot() and matrix rows: an open sum of products, regrouped with whatever
// consumes it.
Adv sumOfProducts(std::span<const Adv> a, std::span<const Adv> b);
bool isUndefined(const Adv& x);

}  // namespace snell::adversary

template <>
struct snell::glsl::IsNumber<snell::adversary::Adv> : std::true_type {};
