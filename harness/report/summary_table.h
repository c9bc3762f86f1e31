#pragma once
// The table `snell run` prints: case, backend, status, vectors, worst slack, time.
#include <ostream>
#include <vector>

#include "runner/case_result.h"

namespace snell {

void printSummaryTable(std::ostream& out, const std::vector<CaseResult>& results);

}  // namespace snell
