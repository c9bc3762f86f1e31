// One `snell eval` input line: text that is not JSON throws
// nlohmann::json::exception, JSON that is not a call throws UsageError.
#include <cstddef>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

#include "core/errors.h"
#include "runner/eval_line.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    snell::parseEvalLine(std::string(reinterpret_cast<const char*>(data), size));
  } catch (const nlohmann::json::exception&) {
  } catch (const snell::UsageError&) {
  }
  return 0;
}
