#include "baseline/baseline_judgement.h"

#include <fmt/format.h>
#include <fmt/ostream.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <map>
#include <set>

namespace snell {
namespace {

Outcome judge(const Expectations& e, const CaseResult& r, JudgedCase& judged) {
  judged.knownFailure = e.knownFailure(r.caseId);
  if (!isFailure(r.status)) return judged.knownFailure ? Outcome::UnexpectedPass : Outcome::Pass;
  if (judged.knownFailure && judged.knownFailure->status == r.status) return Outcome::ExpectedFail;
  judged.flakePattern = e.flake(r.caseId);
  if (judged.flakePattern) return Outcome::KnownFlake;
  if (r.passedOnRerun()) return Outcome::Flake;
  return Outcome::UnexpectedFail;
}

}  // namespace

const char* outcomeName(Outcome outcome) {
  switch (outcome) {
    case Outcome::Pass:
      return "Pass";
    case Outcome::ExpectedFail:
      return "ExpectedFail";
    case Outcome::KnownFlake:
      return "KnownFlake";
    case Outcome::Flake:
      return "Flake";
    case Outcome::UnexpectedPass:
      return "UnexpectedPass";
    case Outcome::UnexpectedFail:
      return "UnexpectedFail";
  }
  return "?";
}

std::size_t BaselineReport::count(Outcome outcome) const {
  return static_cast<std::size_t>(std::count_if(
      cases.begin(), cases.end(), [&](const JudgedCase& c) { return c.outcome == outcome; }));
}

bool isUnexpectedFailure(const ExpectationSet& expectations, const CaseResult& result) {
  CaseResult firstRun = result;
  firstRun.reruns.clear();
  JudgedCase ignored;
  return judge(expectations.of(result.backend), firstRun, ignored) == Outcome::UnexpectedFail;
}

BaselineReport judgeResults(const ExpectationSet& expectations,
                            const std::vector<CaseResult>& results,
                            std::vector<SkippedCase> skipped) {
  BaselineReport report;
  report.skipped = std::move(skipped);
  std::set<std::pair<std::string, std::string>> ran, skippedKeys;
  for (const CaseResult& r : results) {
    JudgedCase judged;
    judged.result = &r;
    judged.outcome = judge(expectations.of(r.backend), r, judged);
    report.cases.push_back(judged);
    ran.emplace(r.backend, r.caseId);
  }
  for (const SkippedCase& s : report.skipped) skippedKeys.emplace(s.backend, s.caseId);
  for (const auto& [backend, e] : expectations.byBackend)
    for (const KnownFailure& f : e.fails)
      if (!ran.count({backend, f.caseId}) && !skippedKeys.count({backend, f.caseId}))
        report.absent.push_back({backend, &f});
  return report;
}

void printBaselineReport(std::ostream& out, const ExpectationSet& expectations,
                         const BaselineReport& report) {
  fmt::print(out,
             "\nExpectations{}: {} unexpected failures, {} expected failures, {} known flakes, "
             "{} flakes, {} improvements, {} skipped, {} absent\n",
             expectations.empty() ? " (none given)" : " " + expectations.source,
             report.count(Outcome::UnexpectedFail), report.count(Outcome::ExpectedFail),
             report.count(Outcome::KnownFlake), report.count(Outcome::Flake),
             report.count(Outcome::UnexpectedPass), report.skipped.size(), report.absent.size());
  // One fails line may cover several backends (a PREFIX-fails.txt is read
  // for each): the backends on which each line's case still fails.
  std::map<std::string, std::vector<std::string>> stillFailing;  // by FILE:LINE
  for (const JudgedCase& c : report.cases)
    if (c.knownFailure && c.outcome != Outcome::UnexpectedPass)
      stillFailing[c.knownFailure->place.where()].push_back(c.result->backend);
  for (const JudgedCase& c : report.cases) {
    const CaseResult& r = *c.result;
    switch (c.outcome) {
      case Outcome::UnexpectedFail:
        if (c.knownFailure)
          fmt::print(out, "  unexpected: {} {} is {}, but {} expects {}\n", r.backend, r.caseId,
                     statusName(r.status), c.knownFailure->place.where(),
                     statusName(c.knownFailure->status));
        else
          fmt::print(out,
                     "  unexpected: {} {} is {}{}; if it is a known failure, add `{},{}` to "
                     "the {} fails file\n",
                     r.backend, r.caseId, statusName(r.status),
                     r.reruns.empty() ? "" : " (reruns: " + r.rerunsText() + ")", r.caseId,
                     statusName(r.status), r.backend);
        break;
      case Outcome::Flake:
        fmt::print(out, "  flake: {} {} was {}, then on rerun {}\n", r.backend, r.caseId,
                   statusName(r.status), r.rerunsText());
        break;
      case Outcome::KnownFlake:
        fmt::print(out, "  known flake: {} {} is {} ({}: {})\n", r.backend, r.caseId,
                   statusName(r.status), c.flakePattern->place.where(), c.flakePattern->pattern);
        break;
      case Outcome::UnexpectedPass:
        if (const auto others = stillFailing.find(c.knownFailure->place.where());
            others != stillFailing.end())
          fmt::print(out,
                     "  improvement: {} {} is {}; {} also covers {}, where it still fails: keep "
                     "it, or give {} a fails file of its own\n",
                     r.backend, r.caseId, statusName(r.status), c.knownFailure->place.where(),
                     fmt::join(others->second, ", "), r.backend);
        else
          fmt::print(out, "  improvement: {} {} is {}; delete {} `{}`\n", r.backend, r.caseId,
                     statusName(r.status), c.knownFailure->place.where(),
                     c.knownFailure->place.text);
        break;
      case Outcome::ExpectedFail:
        fmt::print(
            out, "  expected: {} {} is {} ({}{})\n", r.backend, r.caseId, statusName(r.status),
            c.knownFailure->place.where(),
            c.knownFailure->metadata.reason.empty() ? "" : ": " + c.knownFailure->metadata.reason);
        break;
      case Outcome::Pass:
        break;
    }
  }
  for (const AbsentCase& a : report.absent)
    fmt::print(out, "  absent: {} {} ({}) did not run\n", a.backend, a.entry->caseId,
               a.entry->place.where());
  for (const SkippedCase& s : report.skipped)
    fmt::print(out, "  skipped: {} {} ({}: {})\n", s.backend, s.caseId, s.pattern->place.where(),
               s.pattern->pattern);
}

}  // namespace snell
