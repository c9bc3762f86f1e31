#pragma once
// What the harness asks of a listing's oracle: given the same uniforms,
// constants and vertex inputs that the backend got, say for every captured
// output component what exact math gives (double), what a strict fp32
// machine gives (float), and which fp32 results the GLSL 4.60 / Vulkan
// precision rules allow ([lo, hi]).
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/expected_values.h"
#include "core/values.h"
#include "oracle/precision_rules.h"

namespace snell {

struct OracleInput {
  const UniformMap& uniforms;      // by the listing's GLSL names
  const ConstantMap& constants;    // the listing's constants as printed (manifest `constants`)
  const AttributeMap& attributes;  // by the listing's GLSL names
  std::size_t vertexCount = 0;
  PrecisionRules rules = PrecisionRules::Glsl;  // the API whose rules the intervals follow
};

class VertexOracle {
 public:
  virtual ~VertexOracle() = default;
  // The outputs it computes (GLSL names), in the order evaluate() returns them.
  virtual std::vector<std::string> outputs() const = 0;
  // The per-invocation inputs it reads (GLSL names): vertex attributes, or
  // for a fragment listing the values read back at its probes. An oracle
  // that reads the scene only (vertex listings with fixed-function inputs)
  // may leave it empty.
  virtual std::vector<std::string> inputs() const { return {}; }
  // Throws UsageError when a uniform, constant or attribute it needs is missing
  // or has the wrong type.
  virtual std::vector<OracleVarying> evaluate(const OracleInput& input) const = 0;
};

// The oracle registered under `name` (a manifest's `oracle` field); throws
// UsageError naming the known oracles when there is none.
std::unique_ptr<VertexOracle> makeVertexOracle(const std::string& name);
std::vector<std::string> vertexOracleNames();

}  // namespace snell
