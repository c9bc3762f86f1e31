#include "derived/derived_drawing.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/errors.h"
#include "derived/evaluate.h"

namespace snell::derived {
namespace {

constexpr LowerOptions kReference{.doubleOnly = true};

class DrawingVertexOracle final : public VertexOracle {
 public:
  explicit DrawingVertexOracle(Program program) : program_(std::move(program)) {}

  std::vector<std::string> outputs() const override { return outputNames(program_); }
  std::vector<std::string> inputs() const override { return inputNames(program_); }

  // The reference values only (strict, lo and hi stay empty): the reference
  // renderer interpolates `reference` and leaves out what is `undefined`.
  std::vector<OracleVarying> evaluate(const OracleInput& input) const override {
    const UniformMap uniforms = withLegacyState(program_, input.uniforms);
    checkBindings(program_, uniforms, input.attributes, input.vertexCount);
    const auto values = evaluateReference(program_, uniforms, input.attributes, input.vertexCount,
                                          nullptr, nullptr);
    std::vector<OracleVarying> varyings;
    for (std::size_t k = 0; k < program_.outputs.size(); ++k) {
      OracleVarying varying;
      varying.name = program_.outputs[k].name;
      varying.components = static_cast<int>(program_.outputs[k].components.size());
      varying.reference = values[k];
      for (double value : varying.reference)
        varying.undefined.push_back(std::isfinite(value) ? 0 : 1);
      varyings.push_back(std::move(varying));
    }
    return varyings;
  }

 private:
  Program program_;
};

ValueType uniformType(const Binding& binding) {
  if (binding.columns == 3) return ValueType::Mat3;
  if (binding.columns == 4) return ValueType::Mat4;
  switch (binding.components) {
    case 1:
      return ValueType::Float;
    case 2:
      return ValueType::Vec2;
    case 3:
      return ValueType::Vec3;
    default:
      return ValueType::Vec4;
  }
}

class DerivedFragmentOracle final : public FragmentOracle {
 public:
  explicit DerivedFragmentOracle(Program program) : program_(std::move(program)) {
    const Variable& color = program_.outputs.at(0);
    if (color.components.size() != 4)
      throw UsageError(fmt::format(
          "{}: the fragment colour '{}' has {} components; the derived oracle's reference image "
          "reads a vec4",
          program_.file, color.name, color.components.size()));
  }

  std::vector<FragmentInput> inputs() const override {
    std::vector<FragmentInput> inputs;
    for (const Binding& input : program_.inputs) inputs.push_back({input.name, input.components});
    return inputs;
  }
  std::vector<std::string> samplers() const override { return program_.samplersCube; }
  std::vector<std::string> samplers2D() const override { return program_.samplers2D; }
  std::vector<FragmentUniform> uniforms() const override {
    std::vector<FragmentUniform> uniforms;
    for (const Binding& uniform : program_.uniforms)
      uniforms.push_back({uniform.name, uniformType(uniform)});
    return uniforms;
  }

  using FragmentOracle::shade;
  FragmentResult shade(std::span<const double> packed,
                       const FragmentBindings& bindings) const override {
    // One fragment: each input a one-sample stream, the interpolated value
    // rounded to float as the GPU's fp32 varying is.
    AttributeMap inputs;
    std::size_t next = 0;
    for (const Binding& input : program_.inputs) {
      AttributeStream stream{input.name, input.components, {}};
      for (int c = 0; c < input.components; ++c)
        stream.data.push_back(static_cast<float>(packed[next++]));
      inputs.emplace(input.name, std::move(stream));
    }
    LookupFindings findings;
    const auto values =
        evaluateReference(program_, bindings.uniforms, inputs, 1, &bindings, &findings);
    FragmentResult result;
    for (int c = 0; c < 4; ++c) result.color[static_cast<std::size_t>(c)] = values[0][c];
    result.undefined = findings.undefined[0] != 0;
    result.faceEdge = findings.faceEdge[0] != 0;
    return result;
  }

 private:
  Program program_;
};

}  // namespace

std::unique_ptr<VertexOracle> makeDerivedDrawingVertexOracle(const ShaderSource& vertex) {
  return std::make_unique<DrawingVertexOracle>(lowerOutputs(vertex, {}, kReference));
}

std::unique_ptr<FragmentOracle> makeDerivedFragmentOracle(const ShaderSource& fragment) {
  Program program = lowerOutputs(fragment, {}, kReference);
  if (program.outputs.size() != 1)
    throw UsageError(fmt::format(
        "{}: the fragment stage writes {} outputs; the derived oracle's reference image follows "
        "one colour",
        fragment.file, program.outputs.size()));
  return std::make_unique<DerivedFragmentOracle>(std::move(program));
}

}  // namespace snell::derived
