#include "runner/case_result.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

namespace snell {

std::size_t CaseResult::componentsChecked() const {
  std::size_t n = 0;
  for (const VaryingCheck& v : varyings) n += v.checked;
  return n;
}

std::size_t CaseResult::componentsUndefined() const {
  std::size_t n = 0;
  for (const VaryingCheck& v : varyings) n += v.undefined;
  return n;
}

std::size_t CaseResult::componentsFailed() const {
  std::size_t n = 0;
  for (const VaryingCheck& v : varyings) n += v.failed;
  return n;
}

double CaseResult::worstSlack() const {
  double worst = 0;
  for (const VaryingCheck& v : varyings) worst = std::max(worst, v.worstSlack);
  return worst;
}

bool CaseResult::passedOnRerun() const {
  return isFailure(status) &&
         std::any_of(reruns.begin(), reruns.end(), [](Status s) { return !isFailure(s); });
}

Status CaseResult::gateStatus() const { return passedOnRerun() ? Status::Pass : status; }

std::string CaseResult::statusText() const {
  if (reruns.empty()) return statusName(status);
  if (passedOnRerun())
    return fmt::format("{}, then {} on a rerun (Flake)", statusName(status), rerunsText());
  return fmt::format("{} (reruns: {})", statusName(status), rerunsText());
}

std::string CaseResult::rerunsText() const {
  std::vector<std::string> names;
  for (Status s : reruns) names.push_back(statusName(s));
  return fmt::format("{}", fmt::join(names, ", "));
}

}  // namespace snell
