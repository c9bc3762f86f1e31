#pragma once
// Breaks grouped for the table and the JSON summary: one row per function
// or method, backend, input, kind and class, with how many points and the
// angle and eta ranges they span.
#include <string>
#include <vector>

#include "sweep/sweep_run.h"

namespace snell::sweep {

struct BreakGroup {
  std::string function, backend, input, kind, cls;
  std::size_t count = 0;
  double angleMin = 0, angleMax = 0, etaMin = 0, etaMax = 0;
};

std::vector<BreakGroup> groupBreaks(const SweepResult& result);

}  // namespace snell::sweep
