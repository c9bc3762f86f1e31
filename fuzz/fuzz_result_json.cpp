// A worker's result line as the supervisor reads it: parse, convert to a
// CaseResult, and write it back out as the --json report does (jsonText,
// which writes bytes that are not UTF-8 as U+FFFD). Malformed records throw
// nlohmann::json::exception; writing one back must not.
#include <cstddef>
#include <cstdint>
#include <nlohmann/json.hpp>

#include "runner/case_result_json.h"
#include "runner/json_fields.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  snell::CaseResult result;
  try {
    result = snell::caseResultFromJson(nlohmann::json::parse(data, data + size));
  } catch (const nlohmann::json::exception&) {
    return 0;
  }
  (void)snell::jsonText(snell::toJson(result));
  return 0;
}
