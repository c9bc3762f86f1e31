#pragma once
// `snell eval --server`: the input sent to a `snell serve` of the same
// build and backend (runner/eval_server.h), its answers copied out as they
// come. The answers and the summary are the ones `snell eval` would give
// with that backend in its own process.
#include <chrono>
#include <ostream>
#include <string>

#include "runner/builtin_eval.h"

namespace snell {

// Sends what can be read from `input` (a file descriptor) to the end.
// Throws UsageError when no server of this user answers at `socketPath`,
// SetupError when it refuses the request or fails during it (the answers
// it sent before are written first).
// A server that sends nothing for `silence` (stopped by Ctrl-Z, or
// wedged) is given up on, with SetupError: it ends a request whose input
// is quiet for a minute (eval_server.cpp) and answers a chunk in seconds.
inline constexpr std::chrono::seconds kServerSilenceLimit{120};
EvalSummary evaluateOnServer(const std::string& socketPath, const std::string& backend, int input,
                             std::ostream& out,
                             std::chrono::milliseconds silence = kServerSilenceLimit);

}  // namespace snell
