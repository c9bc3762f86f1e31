#pragma once
// A listing's interface by GLSL name, and the checks that the harness's
// values fit it, so that a manifest mistake is a UsageError naming the
// variable rather than a wrong number.
#include <string>
#include <vector>

#include "core/values.h"
#include "oracle/vertex_oracle.h"

namespace snell::listings {

struct InterfaceEntry {
  enum class Kind { Input, Uniform, Constant, Output };
  Kind kind;
  std::string name;
  ValueType type;
};

// Throws UsageError naming `oracle` and the first input, uniform or constant
// that is missing, has another type or size, or (for an input) has fewer
// vertices than input.vertexCount.
void checkOracleInput(const std::string& oracle, const std::vector<InterfaceEntry>& interface,
                      const OracleInput& input);

}  // namespace snell::listings
