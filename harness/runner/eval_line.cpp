#include "runner/eval_line.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/errors.h"

namespace snell {
namespace {

using nlohmann::json;

// At most `limit` bytes of a value the line gave, for a message: a line of
// megabytes is not echoed whole.
std::string shortened(const std::string& text, std::size_t limit = 64) {
  if (text.size() <= limit) return text;
  // Not through a UTF-8 character: back to the start of the one cut.
  while (limit > 0 && (static_cast<unsigned char>(text[limit]) & 0xC0) == 0x80) --limit;
  return text.substr(0, limit) + "...";
}

// A number, or "nan", "inf" or "-inf" (JSON has none of them). A finite
// number past the float range would be an infinity the line did not write.
float number(const json& x, const char* key) {
  if (x.is_number()) {
    const double value = x.get<double>();
    const auto single = static_cast<float>(value);
    if (std::isinf(single))
      throw UsageError(fmt::format(
          "\"{}\" holds {}, past the largest float ({}): it would be read as an infinity; write "
          "\"inf\" or \"-inf\" for one",
          key, shortened(x.dump()), std::numeric_limits<float>::max()));
    return single;
  }
  if (x.is_string()) {
    const std::string text = x.get<std::string>();
    if (text == "nan") return std::numeric_limits<float>::quiet_NaN();
    if (text == "inf") return std::numeric_limits<float>::infinity();
    if (text == "-inf") return -std::numeric_limits<float>::infinity();
  }
  throw UsageError(
      fmt::format("\"{}\" must hold numbers (or the strings \"nan\", \"inf\", \"-inf\")", key));
}

// ` (the line has "Eta": keys are case-sensitive)` where a key differs from
// `key` in case only, else "".
std::string caseNearMiss(const json& object, const std::string& key) {
  for (const auto& [name, value] : object.items())
    if (name != key && name.size() == key.size() &&
        std::equal(name.begin(), name.end(), key.begin(), [](char a, char b) {
          return std::tolower(static_cast<unsigned char>(a)) ==
                 std::tolower(static_cast<unsigned char>(b));
        }))
      return fmt::format(" (the line has \"{}\": keys are case-sensitive)", name);
  return "";
}

std::vector<float> floatVector(const json& object, const char* key) {
  if (!object.contains(key))
    throw UsageError(fmt::format("missing \"{}\"{}", key, caseNearMiss(object, key)));
  const json& value = object.at(key);
  if (!value.is_array() || value.empty() || value.size() > 4)
    throw UsageError(fmt::format("\"{}\" must be an array of 1 to 4 numbers", key));
  std::vector<float> out;
  for (const json& x : value) out.push_back(number(x, key));
  return out;
}

}  // namespace

json parseEvalJson(std::string_view text) {
  // The JSON reader stops at a NUL byte as at the end of the text: what
  // follows it would be dropped without a word.
  if (const std::size_t nul = text.find('\0'); nul != std::string_view::npos)
    throw UsageError(fmt::format(
        "a NUL byte at column {}: a line is one JSON object in text; remove the byte", nul + 1));
  // A key given twice leaves the object with fewer members than keys: the
  // keys are only counted, and named on a second pass only then.
  std::size_t keys = 0;
  const json::parser_callback_t countKeys = [&](int depth, json::parse_event_t event, json&) {
    if (event == json::parse_event_t::key && depth == 1) ++keys;
    return true;
  };
  json object = json::parse(text.begin(), text.end(), countKeys);  // throws json::parse_error
  if (!object.is_object() || object.size() == keys) return object;
  std::vector<std::string> seen;
  std::string twice;
  const json::parser_callback_t nameTwice = [&](int depth, json::parse_event_t event,
                                                json& parsed) {
    if (event == json::parse_event_t::key && depth == 1 && twice.empty()) {
      std::string key = parsed.get<std::string>();
      if (std::find(seen.begin(), seen.end(), key) != seen.end()) twice = key;
      seen.push_back(std::move(key));
    }
    return true;
  };
  const json named = json::parse(text.begin(), text.end(), nameTwice);  // for `twice` only
  throw UsageError(fmt::format("\"{}\" is given twice; give each key once", twice));
}

BuiltinCall parseEvalLine(const std::string& text) { return parseEvalObject(parseEvalJson(text)); }

BuiltinCall parseEvalObject(const json& object) {
  constexpr const char* kFunctions =
      "use \"reflect\" or \"refract\" (a driver or the oracle), or \"fresnel\", \"ior\", "
      "\"critical_angle\" or \"brewster_angle\" (the physics reference)";
  if (!object.is_object()) throw UsageError("expected a JSON object");
  if (!object.contains("fn"))
    throw UsageError(fmt::format("missing \"fn\"{}: {}", caseNearMiss(object, "fn"), kFunctions));
  if (!object.at("fn").is_string())
    throw UsageError(fmt::format("\"fn\" must be a string: {}", kFunctions));
  BuiltinCall call;
  call.fn = object.at("fn").get<std::string>();
  if (call.fn != "reflect" && call.fn != "refract")
    throw UsageError(fmt::format("unknown fn \"{}\": {}", shortened(call.fn), kFunctions));
  call.I = floatVector(object, "I");
  call.N = floatVector(object, "N");
  if (call.I.size() != call.N.size())
    throw UsageError(fmt::format("I has {} components and N has {}: they must match", call.I.size(),
                                 call.N.size()));
  if (call.fn == "refract") {
    if (!object.contains("eta"))
      throw UsageError(
          fmt::format("refract needs a number \"eta\"{}", caseNearMiss(object, "eta")));
    call.eta = number(object.at("eta"), "eta");
  }
  return call;
}

}  // namespace snell
