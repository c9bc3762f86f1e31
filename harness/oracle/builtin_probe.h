#pragma once
// Single built-in calls evaluated by the oracle, for `snell eval`.
#include <span>
#include <string>
#include <vector>

#include "oracle/components.h"
#include "oracle/fma_build.h"
#include "oracle/precision_rules.h"

namespace snell {

struct BuiltinCall {
  std::string fn;           // "reflect" or "refract"
  std::vector<float> I, N;  // 1 to 4 components, same length
  float eta = 1.0f;         // refract only
};

// One way the built-in may go (refract near the critical angle: the zero
// vector or the refracted ray), each component's exact value and interval.
struct BuiltinWay {
  Components<double> value;
  Components<double> lo, hi;
  Components<bool> undefined;  // the spec leaves the component open
};

struct BuiltinResult {
  Components<double> value;   // exact math on the fp32 inputs
  Components<float> strict;   // fp32 evaluation of the defining formula
  Components<double> lo, hi;  // fp32 results the spec allows, per component (the hull of the ways)
  Components<bool> undefined;
  // One, or each way an undecidable branch may go: reflect() has no
  // branch and refract() one (k < 0.0), so there are at most two.
  InlineVector<BuiltinWay, 2> ways;

  // Whether a driver's vector fits one way entirely.
  bool allows(std::span<const float> vector) const;
  // The way `vector` is judged against: one it fits, else the nearest.
  const BuiltinWay& nearestWay(std::span<const float> vector) const;
};

// The road to the bounds: the shortest one that gives the general road's
// bits (refract on exact inputs: oracle/point_builtins.h), or the
// general road alone, for the tests and benchmarks that hold the two side
// by side.
enum class OracleRoad { Shortest, General };

// Throws UsageError for an unknown fn or mismatched lengths. `build`:
// which compiled build of the hottest steps runs (oracle/fma_build.h); the
// same bits either way.
BuiltinResult evaluateBuiltin(const BuiltinCall& call, PrecisionRules rules = PrecisionRules::Glsl,
                              OracleRoad road = OracleRoad::Shortest,
                              OracleBuild build = fastestOracleBuild());

}  // namespace snell
