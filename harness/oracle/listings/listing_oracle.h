#pragma once
// The adapter from the harness's maps to a listing mirrored as a template:
// a listing is a class template Shader<T> with its GLSL globals as members,
// `void main()`, and `template <class V> void visit(V&)` naming its inputs,
// uniforms, constants and outputs. ListingOracle runs it once per vertex for
// double, float and Interval and fills the OracleVaryings.
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "oracle/interval.h"
#include "oracle/listings/interface_checks.h"
#include "oracle/listings/interface_visitors.h"
#include "oracle/vertex_oracle.h"

namespace snell::listings {

template <template <class> class Shader>
class ListingOracle final : public VertexOracle {
 public:
  explicit ListingOracle(std::string name) : name_(std::move(name)) {
    Shader<double> shader{};
    shader.visit(interface_);
  }

  std::vector<std::string> outputs() const override {
    std::vector<std::string> names;
    for (const InterfaceEntry& entry : interface_.entries()) {
      if (entry.kind == InterfaceEntry::Kind::Output) names.push_back(entry.name);
    }
    return names;
  }

  std::vector<std::string> inputs() const override {
    std::vector<std::string> names;
    for (const InterfaceEntry& entry : interface_.entries()) {
      if (entry.kind == InterfaceEntry::Kind::Input) names.push_back(entry.name);
    }
    return names;
  }

  std::vector<OracleVarying> evaluate(const OracleInput& input) const override {
    checkOracleInput(name_, interface_.entries(), input);
    std::vector<OracleVarying> varyings = emptyVaryings(input.vertexCount);
    run<double>(input, varyings);
    run<float>(input, varyings);
    run<Interval>(input, varyings);
    return varyings;
  }

 private:
  std::vector<OracleVarying> emptyVaryings(std::size_t vertexCount) const {
    std::vector<OracleVarying> varyings;
    for (const InterfaceEntry& entry : interface_.entries()) {
      if (entry.kind != InterfaceEntry::Kind::Output) continue;
      OracleVarying varying;
      varying.name = entry.name;
      varying.components = componentCount(entry.type);
      const std::size_t size = vertexCount * static_cast<std::size_t>(varying.components);
      varying.reference.assign(size, 0.0);
      varying.strict.assign(size, 0.0f);
      varying.lo.assign(size, 0.0);
      varying.hi.assign(size, 0.0);
      varying.undefined.assign(size, 0);
      varyings.push_back(std::move(varying));
    }
    return varyings;
  }

  template <class T>
  static void run(const OracleInput& input, std::vector<OracleVarying>& varyings) {
    Shader<T> shader{};
    BindUniforms<T> uniforms(input.uniforms, input.constants);
    shader.visit(uniforms);
    for (std::size_t vertex = 0; vertex < input.vertexCount; ++vertex) {
      BindVertex<T> inputs(input.attributes, vertex);
      shader.visit(inputs);
      shader.main();
      CaptureOutputs<T> outputs(varyings, vertex);
      shader.visit(outputs);
    }
  }

  std::string name_;
  DescribeInterface interface_;
};

template <template <class> class Shader>
std::unique_ptr<VertexOracle> makeListingOracle(std::string name) {
  return std::make_unique<ListingOracle<Shader>>(std::move(name));
}

}  // namespace snell::listings
