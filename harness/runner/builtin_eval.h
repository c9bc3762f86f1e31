#pragma once
// `snell eval`: JSON Lines in, one JSON line out per input line, in order.
// With no backend the oracle answers; with one, the driver computes the
// built-in and the oracle says whether that is within the spec.
#include <istream>
#include <ostream>

#include "backends/backend.h"
#include "oracle/precision_rules.h"

namespace snell {

struct EvalSummary {
  std::size_t answered = 0;
  std::size_t malformed = 0;
  std::size_t outsideSpec = 0;
};

// Reads all of `in` in batches (one draw per function and width per batch),
// so a driver is not called once per line. `backend` may be null (oracle);
// the intervals follow `rules` (a driver is judged by its own API's).
EvalSummary evaluateLines(std::istream& in, std::ostream& out, Backend* backend,
                          PrecisionRules rules);

// The rules a driver of `api` ("OpenGL", "Vulkan") is judged by.
PrecisionRules precisionRulesForApi(const std::string& api);

}  // namespace snell
