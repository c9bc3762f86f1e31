#pragma once
// Built-in calls drawn on a driver: the step of `snell eval` between
// reading the calls and judging them, shared with the pipeline benchmark
// (bench/pipeline) so that it times what eval runs.
#include <span>
#include <vector>

#include "backends/backend.h"
#include "oracle/builtin_probe.h"

namespace snell {

// A call and where its driver vector goes.
struct DrawnCall {
  const BuiltinCall* call = nullptr;
  std::vector<float>* driver = nullptr;
};

// One draw for all calls that share a function and a width, on the calling
// thread (a driver's context is bound to it). Throws SetupError when a
// probe shader does not compile.
void drawBuiltinCalls(std::span<const DrawnCall> calls, Backend& backend);

// How a driver's vector stands against the oracle's answer: outside when it
// fits no way whole; the slack is the largest of the components' against
// the way it fits (or comes nearest), infinite for a NaN.
struct DriverJudgement {
  bool outside = false;
  double worstSlack = 0.0;
};
DriverJudgement judgeDriverVector(const BuiltinResult& oracle, std::span<const float> driver);

}  // namespace snell
