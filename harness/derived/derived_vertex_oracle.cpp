#include "derived/derived_vertex_oracle.h"

#include <utility>

#include "derived/evaluate.h"

namespace snell::derived {
namespace {

class DerivedVertexOracle final : public VertexOracle {
 public:
  explicit DerivedVertexOracle(Program program) : program_(std::move(program)) {}

  std::vector<std::string> outputs() const override {
    std::vector<std::string> names;
    for (const Variable& output : program_.outputs) names.push_back(output.name);
    return names;
  }

  std::vector<std::string> inputs() const override {
    std::vector<std::string> names;
    for (const Binding& input : program_.inputs) names.push_back(input.name);
    return names;
  }

  std::vector<OracleVarying> evaluate(const OracleInput& input) const override {
    return evaluateVaryings(program_, input.uniforms, input.attributes, input.vertexCount,
                            input.rules);
  }

 private:
  Program program_;
};

}  // namespace

std::unique_ptr<VertexOracle> makeDerivedVertexOracle(const ShaderSource& source,
                                                      const std::vector<std::string>& outputs) {
  return std::make_unique<DerivedVertexOracle>(lowerShader(source, outputs));
}

std::unique_ptr<VertexOracle> makeDerivedVectorOracle(const ShaderSource& source,
                                                      const std::vector<OutputRequest>& outputs) {
  return std::make_unique<DerivedVertexOracle>(lowerOutputs(source, outputs));
}

}  // namespace snell::derived
