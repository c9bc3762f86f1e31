#include "runner/case_result.h"

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

}  // namespace snell
