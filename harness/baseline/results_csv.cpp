#include "baseline/results_csv.h"

#include <fmt/format.h>

namespace snell {

std::string toResultsCsv(const BaselineReport& report) {
  std::string csv;
  for (const JudgedCase& c : report.cases) {
    const CaseResult& r = *c.result;
    const bool plain = c.outcome == Outcome::Pass || c.outcome == Outcome::UnexpectedFail;
    csv += fmt::format("{}/{},{},{:.3f}\n", r.backend, r.caseId,
                       plain ? statusName(r.status) : outcomeName(c.outcome), r.seconds);
  }
  return csv;
}

}  // namespace snell
