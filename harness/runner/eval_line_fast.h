#pragma once
// The common shape of a `snell eval` line,
//   {"fn":"refract","I":[x,y,z],"N":[x,y,z],"eta":0.66}
// (any JSON whitespace, keys in any order, 1 to 4 components), read without
// building a JSON document: nlohmann::json::parse of such a line cost more
// than the oracle in a profile of a million lines. Anything else (other or
// repeated keys, escapes, "nan" strings, physics lines, any error) is left
// to parseEvalObject, which gives the same answer or the error message.
#include <optional>
#include <string_view>

#include "oracle/builtin_probe.h"

namespace snell {

// The call, exactly as parseEvalObject(nlohmann::json::parse(text)) gives
// it, or nullopt where this reader does not decide.
std::optional<BuiltinCall> parseCommonEvalLine(std::string_view text);

}  // namespace snell
