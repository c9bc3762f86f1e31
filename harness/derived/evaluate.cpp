#include "derived/evaluate.h"

#include <fmt/format.h>

#include <algorithm>

#include "core/errors.h"
#include "core/legacy_builtins.h"
#include "derived/evaluation.h"
#include "derived/sample_ways.h"
#include "oracle/glsl/glsl.h"
#include "oracle/interval.h"

namespace snell::derived {

using detail::Evaluation;

void checkBindings(const Program& program, const UniformMap& uniforms, const AttributeMap& inputs,
                   std::size_t sampleCount) {
  for (const Binding& binding : program.uniforms) {
    auto found = uniforms.find(binding.name);
    if (found == uniforms.end())
      throw UsageError(fmt::format("{}:{}: the uniform '{}' has no value; bind it in the manifest",
                                   program.file, binding.line, binding.name));
    if (found->second.data.size() != static_cast<std::size_t>(binding.components))
      throw UsageError(fmt::format(
          "{}:{}: the uniform '{}' has {} components, the value bound "
          "to it {}",
          program.file, binding.line, binding.name, binding.components, found->second.data.size()));
  }
  for (const Binding& binding : program.inputs) {
    auto found = inputs.find(binding.name);
    if (found == inputs.end())
      throw UsageError(fmt::format("{}:{}: the input '{}' has no values; bind it in the manifest",
                                   program.file, binding.line, binding.name));
    const AttributeStream& stream = found->second;
    if (stream.components != binding.components ||
        stream.data.size() < sampleCount * static_cast<std::size_t>(binding.components))
      throw UsageError(fmt::format(
          "{}:{}: the input '{}' has {} components; the stream bound to it has {} per sample "
          "and {} values for {} samples",
          program.file, binding.line, binding.name, binding.components, stream.components,
          stream.data.size(), sampleCount));
  }
}

template <class T>
std::vector<std::vector<T>> evaluateProgram(const Program& program, const UniformMap& uniforms,
                                            const AttributeMap& inputs, std::size_t sampleCount,
                                            std::vector<std::uint8_t>* undecided) {
  Evaluation<T> evaluation(program, uniforms, inputs, sampleCount);
  if (undecided) undecided->assign(sampleCount, 0);
  evaluation.undecided_ = undecided;
  return evaluation.run();
}

template std::vector<std::vector<double>> evaluateProgram<double>(const Program&, const UniformMap&,
                                                                  const AttributeMap&, std::size_t,
                                                                  std::vector<std::uint8_t>*);
template std::vector<std::vector<float>> evaluateProgram<float>(const Program&, const UniformMap&,
                                                                const AttributeMap&, std::size_t,
                                                                std::vector<std::uint8_t>*);
template std::vector<std::vector<Interval>> evaluateProgram<Interval>(const Program&,
                                                                      const UniformMap&,
                                                                      const AttributeMap&,
                                                                      std::size_t,
                                                                      std::vector<std::uint8_t>*);

UniformMap withLegacyState(const Program& program, const UniformMap& bound) {
  const bool legacy = std::any_of(program.uniforms.begin(), program.uniforms.end(),
                                  [](const Binding& b) { return b.name.rfind("gl_", 0) == 0; });
  return legacy ? withDerivedLegacyState(bound) : bound;
}

std::vector<std::vector<double>> evaluateReference(
    const Program& program, const UniformMap& uniforms, const AttributeMap& inputs,
    std::size_t sampleCount, const FragmentBindings* textures, LookupFindings* findings) {
  Evaluation<double> evaluation(program, uniforms, inputs, sampleCount);
  evaluation.textures_ = textures;
  if (findings) {
    findings->undefined.assign(sampleCount, 0);
    findings->faceEdge.assign(sampleCount, 0);
  }
  evaluation.findings_ = findings;
  return evaluation.run();
}

std::vector<OracleVarying> evaluateVaryings(const Program& program, const UniformMap& bound,
                                            const AttributeMap& inputs, std::size_t sampleCount,
                                            PrecisionRules rules) {
  const UniformMap uniforms = withLegacyState(program, bound);
  checkBindings(program, uniforms, inputs, sampleCount);
  const UsePrecisionRules active(rules);
  const auto references = evaluateProgram<double>(program, uniforms, inputs, sampleCount);
  const auto stricts = evaluateProgram<float>(program, uniforms, inputs, sampleCount);
  std::vector<std::uint8_t> undecided;
  const auto intervals =
      evaluateProgram<Interval>(program, uniforms, inputs, sampleCount, &undecided);
  std::vector<OracleVarying> varyings;
  for (std::size_t k = 0; k < program.outputs.size(); ++k) {
    OracleVarying varying;
    varying.name = program.outputs[k].name;
    varying.components = static_cast<int>(program.outputs[k].components.size());
    varying.reference = references[k];
    varying.strict = stricts[k];
    for (std::size_t i = 0; i < intervals[k].size(); ++i) {
      const Interval& value = intervals[k][i];
      varying.lo.push_back(value.lo);
      varying.hi.push_back(value.hi);
      const bool undefined = value.undefined || glsl::isUndefined(varying.reference[i]) ||
                             glsl::isUndefined(varying.strict[i]);
      varying.undefined.push_back(undefined ? 1 : 0);
    }
    varyings.push_back(std::move(varying));
  }
  for (std::size_t sample = 0; sample < sampleCount; ++sample)
    if (undecided[sample]) keepWaysApart(program, uniforms, inputs, sample, varyings);
  return varyings;
}

}  // namespace snell::derived
