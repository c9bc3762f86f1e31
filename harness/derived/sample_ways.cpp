#include "derived/sample_ways.h"

#include "derived/evaluate.h"
#include "oracle/branch_paths.h"
#include "oracle/glsl/scalar.h"
#include "oracle/interval.h"
#include "oracle/way_alternatives.h"

namespace snell::derived {
namespace {

// The program's inputs at one sample, as a batch of one.
AttributeMap inputsAt(const Program& program, const AttributeMap& inputs, std::size_t sample) {
  AttributeMap one;
  for (const Binding& binding : program.inputs) {
    const AttributeStream& stream = inputs.at(binding.name);
    const auto components = static_cast<std::size_t>(stream.components);
    const auto first = stream.data.begin() + static_cast<std::ptrdiff_t>(sample * components);
    one[binding.name] =
        AttributeStream{stream.name, stream.components,
                        std::vector<float>(first, first + static_cast<std::ptrdiff_t>(components))};
  }
  return one;
}

// Every output component of a batch of one, in varying order.
template <class T>
std::vector<T> flattened(const std::vector<std::vector<T>>& outputs) {
  std::vector<T> values;
  for (const std::vector<T>& output : outputs)
    values.insert(values.end(), output.begin(), output.end());
  return values;
}

}  // namespace

void keepWaysApart(const Program& program, const UniformMap& uniforms, const AttributeMap& inputs,
                   std::size_t sample, std::vector<OracleVarying>& varyings) {
  const AttributeMap one = inputsAt(program, inputs, sample);
  BranchPaths paths;
  std::vector<std::vector<Interval>> ways;
  std::vector<std::vector<bool>> traces;
  bool kept = false;
  {
    const UseBranchPaths active(&paths);
    kept = paths.explore([&] {
      ways.push_back(flattened(evaluateProgram<Interval>(program, uniforms, one, 1)));
      traces.push_back(paths.trace());
    });
  }
  if (!kept) {
    ways.erase(ways.begin(), ways.end() - 1);
    for (OracleVarying& varying : varyings) ++varying.mergedToHull;
  }
  std::size_t offset = 0;
  for (OracleVarying& varying : varyings) {
    const auto components = static_cast<std::size_t>(varying.components);
    for (std::size_t c = 0; c < components; ++c) {
      Interval value = ways[0][offset + c];
      for (std::size_t w = 1; w < ways.size(); ++w) value = hull(value, ways[w][offset + c]);
      const std::size_t i = sample * components + c;
      varying.lo[i] = value.lo;
      varying.hi[i] = value.hi;
      const bool undefined = value.undefined || glsl::isUndefined(varying.reference[i]) ||
                             glsl::isUndefined(varying.strict[i]);
      varying.undefined[i] = undefined ? 1 : 0;
    }
    offset += components;
  }
  if (ways.size() < 2) return;
  std::vector<std::vector<double>> references;
  for (const std::vector<bool>& trace : traces) {
    BranchReplay replay(trace);
    const UseBranchReplay replaying(&replay);
    references.push_back(flattened(evaluateProgram<double>(program, uniforms, one, 1)));
  }
  addWayAlternatives(varyings, sample, ways, references);
}

}  // namespace snell::derived
