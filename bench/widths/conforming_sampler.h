#pragma once
// A conforming fp32 machine that makes its legal choices from a seeded
// random stream: which grouping of each sum and product chain, whether to
// fuse a product into an addition, the rounding direction, whether to flush
// denormal results, and where in its allowance a division, inversesqrt,
// exp2 or log2 lands (often at the edge). Its results are "conforming
// values": every one must lie inside a sound interval.
#include <cstdint>
#include <random>
#include <span>

#include "widths/chain.h"
#include "widths/fp32_grid.h"

namespace snell::widths {

// How the machine chooses; set per evaluation with UseSamplerChoices.
struct SamplerChoices {
  Rounding rounding = Rounding::Nearest;
  bool randomRoundingPerOperation = false;
  bool mayFuse = true;
  bool flushDenormals = false;
  bool edgeOfAllowance = true;  // put looser operations at (just inside) their bound
  std::uint64_t seed = 1;
};

struct SampledValue {
  float v = 0.0f;
};

struct SamplerArith {
  using Value = SampledValue;
  static Value point(float x) { return {x}; }
  static Value neg(const Value& a) { return {-a.v}; }
  static Value add(const Value& a, const Value& b);
  static Value mul(const Value& a, const Value& b);
  static Value fma(const Value& a, const Value& b, const Value& c);
  static Value choose(std::span<const Value> ways);  // one at random (fused ways only if allowed)
  static Value div(const Value& a, const Value& b);
  static Value inversesqrt(const Value& x);
  static Value sqrt(const Value& x);
  static Value exp2(const Value& x);
  static Value exp(const Value& x);
  static Value log2(const Value& x);
  static Value pow(const Value& x, const Value& y);
  static Value max(const Value& a, const Value& b) { return {b.v > a.v ? b.v : a.v}; }
  static Value min(const Value& a, const Value& b) { return {b.v < a.v ? b.v : a.v}; }
  static Value abs(const Value& x) { return {x.v < 0 ? -x.v : x.v}; }
  static bool less(const Value& a, const Value& b) { return a.v < b.v; }
  static bool isUndefined(const Value& x) { return x.v != x.v; }
};

using Sampled = Chain<SamplerArith>;

class UseSamplerChoices {
 public:
  explicit UseSamplerChoices(const SamplerChoices& choices);
  ~UseSamplerChoices();
  UseSamplerChoices(const UseSamplerChoices&) = delete;
  UseSamplerChoices& operator=(const UseSamplerChoices&) = delete;
};

}  // namespace snell::widths
