#pragma once
// What `snell eval` and `snell serve` set up alike, so that a server
// answers exactly as eval with the driver in its own process does.
#include <memory>
#include <string>

#include "backends/backend.h"
#include "runner/builtin_eval.h"

namespace snell::cli {

// The driver of `backend`, keeping its compiled programs where a run keeps
// its oracle results.
std::unique_ptr<Backend> makeEvalBackend(const std::string& backend, const std::string& device,
                                         const std::string& glProvider);

// Chunk size and threads: SNELL_EVAL_CHUNK and SNELL_EVAL_THREADS when set
// (whole numbers of at least 1, else a UsageError), else the defaults.
EvalOptions evalOptionsFromEnvironment();

}  // namespace snell::cli
