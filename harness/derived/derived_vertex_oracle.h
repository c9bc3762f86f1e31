#pragma once
// A VertexOracle (oracle/vertex_oracle.h) derived from a shader's own text:
// the listing's GLSL lowered once (lower_glsl.h), then evaluated for
// double, float and Interval over every sample (evaluate.h). Uniforms and
// inputs are bound by their GLSL names; the manifest's `constants` are not
// read, because the shader's own text says what its constants are.
#include <memory>
#include <string>
#include <vector>

#include "derived/lower_glsl.h"
#include "oracle/vertex_oracle.h"

namespace snell::derived {

// Throws UsageError when the shader is outside the subset (naming the
// construct and its line) or does not compute a requested output.
std::unique_ptr<VertexOracle> makeDerivedVertexOracle(const ShaderSource& source,
                                                      const std::vector<std::string>& outputs = {});
// The same for any stage's captured values, each where it is captured: a
// fragment stage's oracle reads its `in` variables as inputs (the values
// read back at the probes) and computes the requested locals.
std::unique_ptr<VertexOracle> makeDerivedVectorOracle(const ShaderSource& source,
                                                      const std::vector<OutputRequest>& outputs);

}  // namespace snell::derived
