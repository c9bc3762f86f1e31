#include "derived/derived_vertex_oracle.h"

#include <optional>
#include <utility>

#include "core/errors.h"
#include "derived/evaluate.h"

namespace snell::derived {

ApiPrograms lowerForEachApi(const ShaderSource& source, const std::vector<OutputRequest>& outputs) {
  ApiPrograms programs{lowerOutputs(source, outputs), std::nullopt};
  if (testsVulkanMacro(source.text)) {
    LowerOptions vulkan;
    vulkan.vulkanMacros = true;
    try {
      programs.vulkan = lowerOutputs(source, outputs, vulkan);
    } catch (const UsageError&) {
      programs.vulkan.reset();
    }
  }
  return programs;
}

namespace {

class DerivedVertexOracle final : public VertexOracle {
 public:
  explicit DerivedVertexOracle(ApiPrograms programs) : programs_(std::move(programs)) {}

  std::vector<std::string> outputs() const override { return outputNames(programs_.openGl); }
  std::vector<std::string> inputs() const override { return inputNames(programs_.openGl); }

  std::vector<OracleVarying> evaluate(const OracleInput& input) const override {
    return evaluateVaryings(programs_.forRules(input.rules), input.uniforms, input.attributes,
                            input.vertexCount, input.rules);
  }

 private:
  ApiPrograms programs_;
};

}  // namespace

std::unique_ptr<VertexOracle> makeDerivedVertexOracle(const ShaderSource& source,
                                                      const std::vector<std::string>& outputs) {
  std::vector<OutputRequest> requests;
  for (const std::string& name : outputs) requests.push_back({name, 0});
  return makeDerivedVectorOracle(source, requests);
}

std::unique_ptr<VertexOracle> makeDerivedVectorOracle(const ShaderSource& source,
                                                      const std::vector<OutputRequest>& outputs) {
  return std::make_unique<DerivedVertexOracle>(lowerForEachApi(source, outputs));
}

}  // namespace snell::derived
