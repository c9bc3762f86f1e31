#include "report/summary_table.h"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace snell {
namespace {

// "-" where nothing was held against an interval: 0.000 would read as a perfect match.
std::string slackText(const CaseResult& r) {
  if (r.componentsChecked() == 0) return "-";
  const double s = r.worstSlack();
  return std::isfinite(s) ? fmt::format("{:.3f}", s) : "inf";
}

// The count and, where anything was read back, the fraction of components
// the spec leaves undefined (a manifest's max_undefined bounds it).
std::string undefinedText(const CaseResult& r) {
  const std::size_t undefined = r.componentsUndefined();
  const std::size_t all = undefined + r.componentsChecked();
  if (all == 0) return "-";
  return fmt::format("{} ({:.1f}%)", undefined, 100.0 * static_cast<double>(undefined) / all);
}

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
  fmt::print(out, "{:<{}}  {:<7}  {:<20}  {:>8}  {:>15}  {:>11}  {:>10}  {:>8}\n", "case", idWidth,
             "backend", "status", "vectors", "undefined", "worst slack", "image err", "time");
  bool atTheEdge = false;
  for (const CaseResult& r : results) {
    fmt::print(out, "{:<{}}  {:<7}  {:<20}  {:>8}  {:>15}  {:>11}  {:>10}  {:>7.3f}s\n", r.caseId,
               idWidth, r.backend, statusName(r.status), r.vectorsChecked(), undefinedText(r),
               slackText(r), imageText(r), r.seconds);
    atTheEdge = atTheEdge || (r.componentsChecked() > 0 && r.worstSlack() == 1.0);
  }
  if (atTheEdge)
    fmt::print(out,
               "worst slack 1.000: a value on the edge of its interval, allowed (the interval "
               "is the set of floats the rules allow, and a driver may return its last one)\n");
  std::map<std::string, int> counts;
  for (const CaseResult& r : results) ++counts[statusName(r.status)];
  std::string tally;
  for (const auto& [name, n] : counts) tally += fmt::format("{}{} {}", tally.empty() ? "" : ", ", n, name);
  fmt::print(out, "{} results: {}\n", results.size(), tally.empty() ? "none" : tally);
}

}  // namespace snell
