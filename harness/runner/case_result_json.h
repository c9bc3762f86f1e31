#pragma once
// One JSON object per case and backend, with the driver that produced it.
#include <nlohmann/json.hpp>

#include "runner/case_result.h"

namespace snell {

nlohmann::json toJson(const CaseResult& result);

}  // namespace snell
