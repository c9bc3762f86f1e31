#pragma once
// The adapter from the harness's maps to a listing mirrored as a template:
// a listing is a class template Shader<T> with its GLSL globals as members,
// `void main()`, and `template <class V> void visit(V&)` naming its inputs,
// uniforms, constants and outputs. ListingOracle runs it once per vertex for
// double, float and Interval and fills the OracleVaryings.
#include <algorithm>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "oracle/branch_paths.h"
#include "oracle/interval.h"
#include "oracle/listings/interface_checks.h"
#include "oracle/listings/interface_visitors.h"
#include "oracle/vertex_oracle.h"
#include "oracle/way_alternatives.h"

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
    const UsePrecisionRules rules(input.rules);
    std::vector<OracleVarying> varyings = emptyVaryings(input.vertexCount);
    run<double>(input, varyings);
    run<float>(input, varyings);
    runIntervals(input, varyings);
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

  // Every output component of one run, in visit order.
  template <class T>
  static std::vector<T> outputsOf(Shader<T>& shader) {
    CollectOutputs<T> collect;
    shader.visit(collect);
    return collect.values;
  }

  static void runIntervals(const OracleInput& input, std::vector<OracleVarying>& varyings) {
    Shader<Interval> shader{};
    BindUniforms<Interval> uniforms(input.uniforms, input.constants);
    shader.visit(uniforms);
    Shader<double> replayed{};
    BindUniforms<double> replayedUniforms(input.uniforms, input.constants);
    replayed.visit(replayedUniforms);
    BranchPaths paths;
    const UseBranchPaths active(&paths);
    for (std::size_t vertex = 0; vertex < input.vertexCount; ++vertex) {
      BindVertex<Interval> inputs(input.attributes, vertex);
      shader.visit(inputs);
      std::vector<std::vector<Interval>> ways;
      std::vector<std::vector<bool>> traces;
      const bool kept = paths.explore([&] {
        shader.main();
        ways.push_back(outputsOf(shader));
        traces.push_back(paths.trace());
      });
      if (!kept) {
        ways.erase(ways.begin(), ways.end() - 1);
        for (OracleVarying& v : varyings) ++v.mergedToHull;
      }
      CaptureOutputs<Interval> hullOutputs(varyings, vertex);
      std::vector<Interval> hullValues = ways[0];
      for (std::size_t w = 1; w < ways.size(); ++w)
        for (std::size_t k = 0; k < hullValues.size(); ++k)
          hullValues[k] = hull(hullValues[k], ways[w][k]);
      storeOutputs(shader, hullValues, hullOutputs);
      if (ways.size() < 2) continue;
      BindVertex<double> replayedInputs(input.attributes, vertex);
      replayed.visit(replayedInputs);
      std::vector<std::vector<double>> references;
      for (const std::vector<bool>& trace : traces) {
        BranchReplay replay(trace);
        const UseBranchReplay replaying(&replay);
        replayed.main();
        references.push_back(outputsOf(replayed));
      }
      addWayAlternatives(varyings, vertex, ways, references);
    }
  }

  // Writes `values` (one run's output components) through the capture visitor.
  static void storeOutputs(Shader<Interval>& shader, const std::vector<Interval>& values,
                           CaptureOutputs<Interval>& capture) {
    AssignOutputs<Interval> assign(values);
    shader.visit(assign);
    shader.visit(capture);
  }

  std::string name_;
  DescribeInterface interface_;
};

template <template <class> class Shader>
std::unique_ptr<VertexOracle> makeListingOracle(std::string name) {
  return std::make_unique<ListingOracle<Shader>>(std::move(name));
}

}  // namespace snell::listings
