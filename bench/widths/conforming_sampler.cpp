#include "widths/conforming_sampler.h"

#include <cmath>
#include <limits>

namespace snell::widths {
namespace {

struct SamplerState {
  SamplerChoices choices;
  std::mt19937_64 random{1};
};

thread_local SamplerState state;

Rounding nextRounding() {
  if (!state.choices.randomRoundingPerOperation) return state.choices.rounding;
  return static_cast<Rounding>(state.random() % 4);
}

float finish(float x) {
  if (state.choices.flushDenormals && x != 0 && std::fabs(x) < kMinNormal)
    return std::signbit(x) ? -0.0f : 0.0f;
  return x;
}

float rounded(double head, double tail) { return finish(roundTo(head, tail, nextRounding())); }

// A float within `ulps` ULP of the exact value x: at the edge (just inside
// it, rounded towards x) or correctly rounded.
float withinUlps(double x, double ulps) {
  if (!std::isfinite(x)) return static_cast<float>(x);
  const int pick = static_cast<int>(state.random() % 3);
  if (!state.choices.edgeOfAllowance || pick == 0) return rounded(x, 0.0);
  const double target = x + (pick == 1 ? -1 : 1) * 0.999 * ulps * ulpOf(x);
  return finish(static_cast<float>(pick == 1 ? floatUp(target) : floatDown(target)));
}

float withinDistance(double x, double distance) {
  const int pick = static_cast<int>(state.random() % 3);
  if (!state.choices.edgeOfAllowance || pick == 0) return rounded(x, 0.0);
  const double target = x + (pick == 1 ? -1 : 1) * 0.999 * distance;
  return finish(static_cast<float>(pick == 1 ? floatUp(target) : floatDown(target)));
}

}  // namespace

UseSamplerChoices::UseSamplerChoices(const SamplerChoices& choices) {
  state.choices = choices;
  state.random.seed(choices.seed);
}
UseSamplerChoices::~UseSamplerChoices() { state = SamplerState{}; }

SampledValue SamplerArith::add(const Value& a, const Value& b) {
  double tail = 0;
  const double head = twoSum(a.v, b.v, &tail);
  return {rounded(head, std::isnan(tail) ? 0.0 : tail)};
}

SampledValue SamplerArith::mul(const Value& a, const Value& b) {
  return {rounded(static_cast<double>(a.v) * b.v, 0.0)};  // exact in double
}

// A machine that does not fuse evaluates the same way unfused.
SampledValue SamplerArith::fma(const Value& a, const Value& b, const Value& c) {
  if (!state.choices.mayFuse) return add(mul(a, b), c);
  double tail = 0;
  const double head = twoSum(static_cast<double>(a.v) * b.v, c.v, &tail);
  return {rounded(head, std::isnan(tail) ? 0.0 : tail)};
}

SampledValue SamplerArith::choose(std::span<const Value> ways) {
  return ways[state.random() % ways.size()];
}

SampledValue SamplerArith::div(const Value& a, const Value& b) {
  return {withinUlps(static_cast<double>(a.v) / b.v, 2.5)};
}

SampledValue SamplerArith::inversesqrt(const Value& x) {
  if (x.v < 0) return {std::numeric_limits<float>::quiet_NaN()};
  return {withinUlps(1.0 / std::sqrt(static_cast<double>(x.v)), 2.0)};
}

SampledValue SamplerArith::sqrt(const Value& x) {
  if (x.v == 0) return {0.0f};
  return div(point(1.0f), inversesqrt(x));
}

SampledValue SamplerArith::exp2(const Value& x) {
  return {withinUlps(std::exp2(static_cast<double>(x.v)), 3.0 + 2.0 * std::fabs(x.v))};
}

SampledValue SamplerArith::exp(const Value& x) {
  return {withinUlps(std::exp(static_cast<double>(x.v)), 3.0 + 2.0 * std::fabs(x.v))};
}

SampledValue SamplerArith::log2(const Value& x) {
  if (x.v <= 0) return {std::numeric_limits<float>::quiet_NaN()};
  const double exact = std::log2(static_cast<double>(x.v));
  if (x.v >= 0.5f && x.v <= 2.0f) return {withinDistance(exact, 0x1p-21)};
  return {withinUlps(exact, 3.0)};
}

SampledValue SamplerArith::pow(const Value& x, const Value& y) {
  if (x.v == 0 && y.v > 0) return {0.0f};
  return exp2(mul(y, log2(x)));
}

}  // namespace snell::widths
