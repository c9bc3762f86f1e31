#pragma once
// `snell eval`: JSON Lines in, one JSON line out per input line, in order.
// With no backend the oracle answers; with one, the driver computes the
// built-in and the oracle says whether that is within the spec.
#include <csignal>
#include <cstddef>
#include <functional>
#include <istream>
#include <ostream>
#include <string>

#include "backends/backend.h"
#include "oracle/precision_rules.h"

namespace snell {

struct EvalSummary {
  std::size_t answered = 0;
  std::size_t malformed = 0;
  std::size_t outsideSpec = 0;
  // The first malformed line: its number and what is wrong with it (its
  // "error" answer is "line N: " and this).
  std::size_t firstMalformedLine = 0;
  std::string firstMalformedReason;
  // The errno of a read of the input that failed part way (0: read to its
  // end). The reading process's own: a server reports its socket's failures
  // in its reply, and the client sets this for the input it sends.
  int readError = 0;
  // Input lines answered (blank ones included), and whether a stop request
  // ended the input before its end: the answers are then those of lines 1
  // to linesDone, each whole.
  std::size_t linesDone = 0;
  bool stopped = false;
};

struct EvalOptions {
  // Lines read, drawn and answered together: memory is bounded by one
  // chunk, and a driver draws each chunk in one draw per function and width.
  std::size_t chunkLines = 65536;
  // Threads that parse, run the oracle and write answers (the caller
  // included); a driver is only ever called from the calling thread.
  unsigned threads = 1;
  // Called after each chunk's answers are written, with the lines so far.
  std::function<void(std::size_t lines)> progress;
  // A signal handler's flag: once it is non-zero the input must end
  // (StoppableInputBuffer ends it), and the lines already read are answered
  // except a last one cut short without its newline.
  const volatile std::sig_atomic_t* stop = nullptr;
};

// Reads all of `in` a chunk at a time. `backend` may be null (oracle); the
// intervals follow `rules` (a driver is judged by its own API's). The
// output does not depend on the chunk size or the number of threads.
EvalSummary evaluateLines(std::istream& in, std::ostream& out, Backend* backend,
                          PrecisionRules rules, const EvalOptions& options = {});

// The rules a driver of `api` ("OpenGL", "Vulkan") is judged by.
PrecisionRules precisionRulesForApi(const std::string& api);

}  // namespace snell
