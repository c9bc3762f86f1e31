#pragma once
// `snell eval --server`: the input sent to a `snell serve` of the same
// build and backend (runner/eval_server.h), its answers copied out as they
// come. The answers and the summary are the ones `snell eval` would give
// with that backend in its own process.
#include <ostream>
#include <string>

#include "runner/builtin_eval.h"

namespace snell {

// Sends what can be read from `input` (a file descriptor) to the end.
// Throws UsageError when no server of this user answers at `socketPath`,
// SetupError when it refuses the request or fails during it (the answers
// it sent before are written first).
EvalSummary evaluateOnServer(const std::string& socketPath, const std::string& backend, int input,
                             std::ostream& out);

}  // namespace snell
