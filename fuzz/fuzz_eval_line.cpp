// One `snell eval` input line, read as evaluateLines reads it: text that is
// not JSON throws nlohmann::json::exception; a physics line is answered by
// the physics reference, and JSON that is not a call, or a physics line
// with bad input, throws UsageError.
#include <cstddef>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

#include "core/errors.h"
#include "runner/eval_line.h"
#include "runner/physics_eval_line.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const nlohmann::json object =
        nlohmann::json::parse(std::string(reinterpret_cast<const char*>(data), size));
    if (snell::isPhysicsCall(object))
      snell::evaluatePhysicsCall(object);
    else
      snell::parseEvalObject(object);
  } catch (const nlohmann::json::exception&) {
  } catch (const snell::UsageError&) {
  }
  return 0;
}
