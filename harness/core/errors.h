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

}  // namespace snell
