#pragma once
// Small helpers the case runner, its validation and the check kinds share.
#include <fmt/format.h>

#include <chrono>
#include <string>

#include "core/errors.h"
#include "core/manifest.h"

namespace snell {

inline double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// A manifest problem found while validating a case: "MANIFEST:LINE: what".
[[noreturn]] inline void manifestErrorAt(const Manifest& m, int line, const std::string& what) {
  throw UsageError(fmt::format("{}:{}: {}", m.path.string(), line, what));
}

}  // namespace snell
