#include "derived/derived_vertex_oracle.h"

#include <optional>
#include <utility>

#include "core/errors.h"
#include "derived/evaluate.h"

namespace snell::derived {
namespace {

// One program, or, for a text that tests VULKAN, one for each API's
// preprocessing: the Vulkan one answers under the Vulkan rules, which only a
// Vulkan driver is judged by.
class DerivedVertexOracle final : public VertexOracle {
 public:
  template <class Lower>
  DerivedVertexOracle(const ShaderSource& source, Lower lower) : program_(lower(LowerOptions{})) {
    if (testsVulkanMacro(source.text)) {
      LowerOptions vulkan;
      vulkan.vulkanMacros = true;
      // A Vulkan branch in Vulkan-only GLSL (constant_id, push constants)
      // does not lower through the OpenGL front end: such a text is held
      // against the OpenGL one on both APIs, as before, rather than
      // stopping the run.
      try {
        vulkanProgram_ = lower(vulkan);
      } catch (const UsageError&) {
        vulkanProgram_.reset();
      }
    }
  }

  std::vector<std::string> outputs() const override { return outputNames(program_); }
  std::vector<std::string> inputs() const override { return inputNames(program_); }

  std::vector<OracleVarying> evaluate(const OracleInput& input) const override {
    const Program& program =
        vulkanProgram_ && input.rules == PrecisionRules::Vulkan ? *vulkanProgram_ : program_;
    return evaluateVaryings(program, input.uniforms, input.attributes, input.vertexCount,
                            input.rules);
  }

 private:
  Program program_;
  std::optional<Program> vulkanProgram_;
};

}  // namespace

std::unique_ptr<VertexOracle> makeDerivedVertexOracle(const ShaderSource& source,
                                                      const std::vector<std::string>& outputs) {
  return std::make_unique<DerivedVertexOracle>(
      source, [&](LowerOptions options) { return lowerShader(source, outputs, options); });
}

std::unique_ptr<VertexOracle> makeDerivedVectorOracle(const ShaderSource& source,
                                                      const std::vector<OutputRequest>& outputs) {
  return std::make_unique<DerivedVertexOracle>(
      source, [&](LowerOptions options) { return lowerOutputs(source, outputs, options); });
}

}  // namespace snell::derived
