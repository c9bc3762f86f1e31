#include "runner/eval_line.h"

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "core/errors.h"

namespace snell {
namespace {

using nlohmann::json;

std::vector<float> floatVector(const json& object, const char* key) {
  if (!object.contains(key)) throw UsageError(fmt::format("missing \"{}\"", key));
  const json& value = object.at(key);
  if (!value.is_array() || value.empty() || value.size() > 4)
    throw UsageError(fmt::format("\"{}\" must be an array of 1 to 4 numbers", key));
  std::vector<float> out;
  for (const json& x : value) {
    if (!x.is_number()) throw UsageError(fmt::format("\"{}\" must hold numbers only", key));
    out.push_back(static_cast<float>(x.get<double>()));
  }
  return out;
}

}  // namespace

BuiltinCall parseEvalLine(const std::string& text) {
  const json object = json::parse(text);  // throws json::parse_error
  if (!object.is_object()) throw UsageError("expected a JSON object");
  if (!object.contains("fn") || !object.at("fn").is_string())
    throw UsageError("missing \"fn\": use \"reflect\" or \"refract\"");
  BuiltinCall call;
  call.fn = object.at("fn").get<std::string>();
  if (call.fn != "reflect" && call.fn != "refract")
    throw UsageError(fmt::format("unknown fn \"{}\": use \"reflect\" or \"refract\"", call.fn));
  call.I = floatVector(object, "I");
  call.N = floatVector(object, "N");
  if (call.I.size() != call.N.size())
    throw UsageError(fmt::format("I has {} components and N has {}: they must match",
                                 call.I.size(), call.N.size()));
  if (call.fn == "refract") {
    if (!object.contains("eta") || !object.at("eta").is_number())
      throw UsageError("refract needs a number \"eta\"");
    call.eta = static_cast<float>(object.at("eta").get<double>());
  }
  return call;
}

}  // namespace snell
