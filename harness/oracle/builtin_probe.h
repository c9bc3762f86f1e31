#pragma once
// Single built-in calls evaluated by the oracle, for `snell eval`.
#include <string>
#include <vector>

namespace snell {

struct BuiltinCall {
  std::string fn;             // "reflect" or "refract"
  std::vector<float> I, N;    // 1 to 4 components, same length
  float eta = 1.0f;           // refract only
};

struct BuiltinResult {
  std::vector<double> value;   // exact math on the fp32 inputs
  std::vector<float> strict;   // fp32 evaluation of the defining formula
  std::vector<double> lo, hi;  // fp32 results the spec allows, per component
};

// Throws UsageError for an unknown fn or mismatched lengths.
BuiltinResult evaluateBuiltin(const BuiltinCall& call);

}  // namespace snell
