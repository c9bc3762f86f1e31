// A worker's result line as the supervisor reads it: parse, convert to a
// CaseResult, and write it back out as the --json report would. Malformed
// records throw nlohmann::json::exception (so does dumping invalid UTF-8).
#include <cstddef>
#include <cstdint>
#include <nlohmann/json.hpp>

#include "runner/case_result_json.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const snell::CaseResult result = snell::caseResultFromJson(nlohmann::json::parse(data, data + size));
    (void)snell::toJson(result).dump();
  } catch (const nlohmann::json::exception&) {
  }
  return 0;
}
