#include "runner/eval_line.h"

#include <fmt/format.h>

#include <limits>
#include <nlohmann/json.hpp>

#include "core/errors.h"

namespace snell {
namespace {

using nlohmann::json;

// A number, or "nan", "inf" or "-inf" (JSON has none of them).
float number(const json& x, const char* key) {
  if (x.is_number()) return static_cast<float>(x.get<double>());
  if (x.is_string()) {
    const std::string text = x.get<std::string>();
    if (text == "nan") return std::numeric_limits<float>::quiet_NaN();
    if (text == "inf") return std::numeric_limits<float>::infinity();
    if (text == "-inf") return -std::numeric_limits<float>::infinity();
  }
  throw UsageError(
      fmt::format("\"{}\" must hold numbers (or the strings \"nan\", \"inf\", \"-inf\")", key));
}

std::vector<float> floatVector(const json& object, const char* key) {
  if (!object.contains(key)) throw UsageError(fmt::format("missing \"{}\"", key));
  const json& value = object.at(key);
  if (!value.is_array() || value.empty() || value.size() > 4)
    throw UsageError(fmt::format("\"{}\" must be an array of 1 to 4 numbers", key));
  std::vector<float> out;
  for (const json& x : value) out.push_back(number(x, key));
  return out;
}

}  // namespace

BuiltinCall parseEvalLine(const std::string& text) {
  return parseEvalObject(json::parse(text));  // throws json::parse_error
}

BuiltinCall parseEvalObject(const json& object) {
  constexpr const char* kFunctions =
      "use \"reflect\" or \"refract\" (a driver or the oracle), or \"fresnel\", \"ior\", "
      "\"critical_angle\" or \"brewster_angle\" (the physics reference)";
  if (!object.is_object()) throw UsageError("expected a JSON object");
  if (!object.contains("fn") || !object.at("fn").is_string())
    throw UsageError(fmt::format("missing \"fn\": {}", kFunctions));
  BuiltinCall call;
  call.fn = object.at("fn").get<std::string>();
  if (call.fn != "reflect" && call.fn != "refract")
    throw UsageError(fmt::format("unknown fn \"{}\": {}", call.fn, kFunctions));
  call.I = floatVector(object, "I");
  call.N = floatVector(object, "N");
  if (call.I.size() != call.N.size())
    throw UsageError(fmt::format("I has {} components and N has {}: they must match", call.I.size(),
                                 call.N.size()));
  if (call.fn == "refract") {
    if (!object.contains("eta")) throw UsageError("refract needs a number \"eta\"");
    call.eta = number(object.at("eta"), "eta");
  }
  return call;
}

}  // namespace snell
