#pragma once
// One JSON object per case and backend, with the driver that produced it:
// the line workers send the supervisor and the record --json writes.
#include <nlohmann/json.hpp>

#include "runner/case_result.h"

namespace snell {

nlohmann::json toJson(const CaseResult& result);
// The inverse of toJson; throws nlohmann::json::exception on a malformed record.
CaseResult caseResultFromJson(const nlohmann::json& json);

}  // namespace snell
