#include "baseline/results_csv.h"

#include <fmt/format.h>

#include <string>

namespace snell {
namespace {

// deqp-runner reads a fixed set of statuses (Pass, Fail, Crash, Skip,
// Flake, KnownFlake, Warn, Missing, ExpectedFail, Timeout and
// UnexpectedImprovement(STATUS)) and refuses any other: snell's own are
// named as the nearest of those. The JSON record keeps snell's own.
const char* deqpRunnerStatus(Status status) {
  switch (status) {
    case Status::Pass:
    case Status::ExpectedCompileError:  // a listing that must not compile, and did not
      return "Pass";
    case Status::NotSupported:
      return "Skip";
    case Status::CompatibilityWarning:
    case Status::QualityWarning:
      return "Warn";
    case Status::Fail:
    case Status::CompileError:
      return "Fail";
    case Status::Timeout:
      return "Timeout";
    case Status::Crash:
      return "Crash";
  }
  return "Fail";
}

std::string csvStatus(const JudgedCase& c) {
  switch (c.outcome) {
    case Outcome::Pass:
    case Outcome::UnexpectedFail:
      return deqpRunnerStatus(c.result->status);
    case Outcome::UnexpectedPass:
      return fmt::format("UnexpectedImprovement({})", deqpRunnerStatus(c.result->status));
    case Outcome::ExpectedFail:
    case Outcome::KnownFlake:
    case Outcome::Flake:
      return outcomeName(c.outcome);
  }
  return outcomeName(c.outcome);
}

}  // namespace

std::string toResultsCsv(const BaselineReport& report) {
  std::string csv;
  for (const JudgedCase& c : report.cases)
    csv += fmt::format("{}/{},{},{:.3f}\n", c.result->backend, c.result->caseId, csvStatus(c),
                       c.result->seconds);
  return csv;
}

}  // namespace snell
