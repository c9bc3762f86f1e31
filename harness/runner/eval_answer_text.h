#pragma once
// One `snell eval` answer for a reflect/refract line, written straight as
// text, byte for byte what nlohmann::json's dump() wrote for it before:
// keys in sorted order, numbers by nlohmann's own shortest round-trip
// conversion, non-finite numbers as the strings "inf", "-inf" and "nan".
// Building a JSON document per answer and dumping it cost more than the
// oracle in a profile of a million lines.
#include <fmt/format.h>

#include <cstddef>
#include <vector>

#include "oracle/builtin_probe.h"
#include "oracle/precision_rules.h"

namespace snell {

// What the oracle answers, with the driver's vector where there is one.
struct EvalAnswer {
  std::size_t line = 0;
  const BuiltinCall* call = nullptr;
  const BuiltinResult* oracle = nullptr;
  const std::vector<float>* driver = nullptr;  // null: the oracle alone answers
  PrecisionRules rules = PrecisionRules::Glsl;
};

// Appends the answer and a newline; returns whether a driver's vector lies
// outside the spec (false for the oracle alone).
bool appendEvalAnswer(fmt::memory_buffer& out, const EvalAnswer& answer);

}  // namespace snell
