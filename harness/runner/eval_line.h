#pragma once
// One line of `snell eval` input: {"fn":"refract","I":[...],"N":[...],"eta":0.66}.
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "oracle/builtin_probe.h"

namespace snell {

// One line's JSON. Throws nlohmann::json::exception for text that is not
// JSON, UsageError for a key given twice in the line's object (JSON leaves
// it open which one counts).
nlohmann::json parseEvalJson(std::string_view text);

// Throws nlohmann::json::exception for text that is not JSON, UsageError
// for JSON that is not a call (unknown fn, wrong lengths, missing eta).
BuiltinCall parseEvalLine(const std::string& text);
BuiltinCall parseEvalObject(const nlohmann::json& object);

}  // namespace snell
