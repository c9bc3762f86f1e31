#include "report/summary_table.h"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <algorithm>
#include <map>

#include "runner/checks/check_kind.h"

namespace snell {

void printSummaryTable(std::ostream& out, const std::vector<CaseResult>& results) {
  std::size_t idWidth = 4, backendWidth = 7;
  for (const CaseResult& r : results) {
    idWidth = std::max(idWidth, r.caseId.size());
    backendWidth = std::max(backendWidth, r.backend.size());
  }
  // Each check kind brings its own columns (runner/checks/).
  std::vector<SummaryColumn> columns;
  for (const auto& kind : checkKinds())
    for (SummaryColumn& column : kind->summaryColumns()) columns.push_back(std::move(column));
  fmt::print(out, "{:<{}}  {:<{}}  {:<20}", "case", idWidth, "backend", backendWidth, "status");
  for (const SummaryColumn& column : columns)
    fmt::print(out, "  {:>{}}", column.header, column.width);
  fmt::print(out, "  {:>8}\n", "time");
  bool atTheEdge = false;
  for (const CaseResult& r : results) {
    fmt::print(out, "{:<{}}  {:<{}}  {:<20}", r.caseId, idWidth, r.backend, backendWidth,
               statusName(r.status));
    for (const SummaryColumn& column : columns)
      fmt::print(out, "  {:>{}}", column.cell(r), column.width);
    fmt::print(out, "  {:>7.3f}s\n", r.seconds);
    atTheEdge = atTheEdge || (r.componentsChecked() > 0 && r.worstSlack() == 1.0);
  }
  if (atTheEdge)
    fmt::print(out,
               "worst slack 1.000: a value on the edge of its interval, allowed (the interval "
               "is the set of floats the rules allow, and a driver may return its last one)\n");
  std::map<std::string, int> counts;
  for (const CaseResult& r : results) ++counts[statusName(r.status)];
  std::string tally;
  for (const auto& [name, n] : counts)
    tally += fmt::format("{}{} {}", tally.empty() ? "" : ", ", n, name);
  fmt::print(out, "{} results: {}\n", results.size(), tally.empty() ? "none" : tally);
}

}  // namespace snell
