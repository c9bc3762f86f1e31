#pragma once
// JUnit XML, the format CI systems (GitLab, Jenkins, GitHub) show natively.
#include <string>
#include <vector>

#include "runner/case_result.h"

namespace snell {

std::string toJUnitXml(const std::vector<CaseResult>& results);

}  // namespace snell
