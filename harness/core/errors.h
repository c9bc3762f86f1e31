#pragma once
// Two kinds of failure, kept apart because they map to different exit codes:
// a UsageError is the user's to fix (bad flag, bad manifest: exit 2); a
// SetupError means the machine cannot run a backend at all (exit 2 too, but
// the message points at drivers and packages instead of at a file).
#include <stdexcept>
#include <string>

namespace snell {

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct SetupError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A command stopped part way by SIGINT or SIGTERM (runner/interrupt_flag.h):
// exit 128 + the signal, with what became of its work as the message.
struct Interrupted : std::runtime_error {
  Interrupted(int signalNumber, const std::string& what)
      : std::runtime_error(what), signal(signalNumber) {}
  int signal;
};

// A library's exception text as a user reads it inside a message:
// nlohmann's "[json.exception.out_of_range.403] key 'x' not found" without
// its bracketed id.
inline std::string readableError(const std::exception& error) {
  std::string text = error.what();
  if (text.rfind("[json.exception.", 0) == 0) {
    const std::size_t end = text.find("] ");
    if (end != std::string::npos) text.erase(0, end + 2);
  }
  return text;
}

}  // namespace snell
