#include "report/summary_table.h"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace snell {
namespace {

std::string slackText(double s) { return std::isfinite(s) ? fmt::format("{:.3f}", s) : "inf"; }

// The largest error against the CPU reference, or "-" for a case that draws nothing.
std::string imageText(const CaseResult& r) {
  for (const ImageComparison& c : r.images)
    if (c.against == "reference") return fmt::format("{:.2e}", c.maxError);
  return "-";
}

}  // namespace

void printSummaryTable(std::ostream& out, const std::vector<CaseResult>& results) {
  std::size_t idWidth = 4;
  for (const CaseResult& r : results) idWidth = std::max(idWidth, r.caseId.size());
  fmt::print(out, "{:<{}}  {:<7}  {:<20}  {:>8}  {:>10}  {:>11}  {:>10}  {:>8}\n", "case", idWidth,
             "backend", "status", "vectors", "undefined", "worst slack", "image err", "time");
  for (const CaseResult& r : results)
    fmt::print(out, "{:<{}}  {:<7}  {:<20}  {:>8}  {:>10}  {:>11}  {:>10}  {:>7.3f}s\n", r.caseId,
               idWidth, r.backend, statusName(r.status), r.vectorsChecked(),
               r.componentsUndefined(), slackText(r.worstSlack()), imageText(r), r.seconds);
  std::map<std::string, int> counts;
  for (const CaseResult& r : results) ++counts[statusName(r.status)];
  std::string tally;
  for (const auto& [name, n] : counts) tally += fmt::format("{}{} {}", tally.empty() ? "" : ", ", n, name);
  fmt::print(out, "{} results: {}\n", results.size(), tally.empty() ? "none" : tally);
}

}  // namespace snell
