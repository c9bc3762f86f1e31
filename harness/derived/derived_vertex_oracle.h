#pragma once
// A VertexOracle (oracle/vertex_oracle.h) derived from a shader's own text:
// the listing's GLSL lowered once (lower_glsl.h), then evaluated for
// double, float and Interval over every sample (evaluate.h). Uniforms and
// inputs are bound by their GLSL names; the manifest's `constants` are not
// read, because the shader's own text says what its constants are.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "derived/ir.h"
#include "derived/lower_glsl.h"
#include "oracle/precision_rules.h"
#include "oracle/vertex_oracle.h"

namespace snell::derived {

// A text's programs: the one OpenGL's preprocessing gives and, for a text
// that tests VULKAN, the one a Vulkan compiler's gives, which answers under
// the Vulkan rules (only a Vulkan driver is judged by them). A Vulkan branch
// in Vulkan-only GLSL (constant_id, push constants) does not lower through
// the OpenGL front end: such a text is held against the OpenGL program on
// both APIs.
struct ApiPrograms {
  Program openGl;
  std::optional<Program> vulkan;
  const Program& forRules(PrecisionRules rules) const {
    return vulkan && rules == PrecisionRules::Vulkan ? *vulkan : openGl;
  }
};
// Throws UsageError as lowerOutputs does (for the OpenGL program).
ApiPrograms lowerForEachApi(const ShaderSource& source, const std::vector<OutputRequest>& outputs);

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
