#include "derived/derived_vertex_oracle.h"

#include <utility>

#include "derived/evaluate.h"

namespace snell::derived {
namespace {

class DerivedVertexOracle final : public VertexOracle {
 public:
  explicit DerivedVertexOracle(Program program) : program_(std::move(program)) {}

  std::vector<std::string> outputs() const override { return outputNames(program_); }
  std::vector<std::string> inputs() const override { return inputNames(program_); }

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
