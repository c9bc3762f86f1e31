#include "adversary/adversary_check.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <utility>

#include "adversary/adversarial_machine.h"
#include "catalog_shaders.h"
#include "core/errors.h"
#include "core/legacy_builtins.h"
#include "derived/derived_vertex_oracle.h"
#include "derived/evaluation.h"
#include "oracle/branch_paths.h"
#include "oracle/builtin_probe.h"
#include "oracle/glsl/glsl.h"
#include "oracle/listings/interface_visitors.h"
#include "oracle/vertex_oracle.h"

namespace snell::adversary {
namespace {

template <class T, int N>
std::vector<T> componentsOf(const glsl::vec<T, N>& v) {
  return std::vector<T>(v.c.begin(), v.c.end());
}

template <class T>
std::vector<T> evaluateFormula(Formula f, const std::vector<T>& in) {
  using glsl::vec3;
  using glsl::vec4;
  const auto v3 = [&](std::size_t k) { return vec3<T>(in[k], in[k + 1], in[k + 2]); };
  const auto v4 = [&](std::size_t k) { return vec4<T>(in[k], in[k + 1], in[k + 2], in[k + 3]); };
  switch (f) {
    case Formula::Reflect:
      return componentsOf(glsl::reflect(v3(0), v3(3)));
    case Formula::Refract:
      return componentsOf(glsl::refract(v3(0), v3(3), in[6]));
    case Formula::Normalize:
      return componentsOf(glsl::normalize(v3(0)));
    case Formula::Length:
      return {glsl::length(v3(0))};
    case Formula::Dot:
      return {glsl::dot(v4(0), v4(4))};
    case Formula::Pow:
      return {pow(in[0], in[1])};
    case Formula::Exp2:
      return {exp2(in[0])};
    case Formula::Log2:
      return {log2(in[0])};
    case Formula::Sqrt:
      return {sqrt(in[0])};
    case Formula::InverseSqrt:
      return {inversesqrt(in[0])};
    case Formula::Mix:
      return componentsOf(glsl::mix(v3(0), v3(3), in[6]));
    case Formula::Clamp:
      return {min(max(in[0], in[1]), in[2])};
    case Formula::Divide:
      return {in[0] / in[1]};
    case Formula::MatrixVector: {
      glsl::mat4<T> m;
      for (int c = 0; c < 4; ++c) m[c] = v4(static_cast<std::size_t>(4 * c));
      return componentsOf(m * v4(16));
    }
    case Formula::FresnelRatio: {
      // Listing 14.1's Ratio with its constants as printed.
      const T one = glsl::lit<T>(1.0);
      const T eta = glsl::lit<T>(0.66);
      const T F = ((one - eta) * (one - eta)) / ((one + eta) * (one + eta));
      const vec3<T> i = v3(0), n = v3(3);
      return {F + (one - F) * pow(one - glsl::dot(-i, n), in[6])};
    }
  }
  throw std::logic_error("unknown formula");
}

using Ways = std::vector<std::vector<Interval>>;

// Every way the oracle allows (one per branch path), as in ListingOracle.
template <class Evaluate>
Ways oracleWays(Evaluate evaluate) {
  Ways ways;
  BranchPaths paths;
  const UseBranchPaths active(&paths);
  const bool kept = paths.explore([&] { ways.push_back(evaluate()); });
  if (!kept) ways.erase(ways.begin(), ways.end() - 1);
  return ways;
}

std::string floats(std::span<const float> v) {
  std::string s;
  for (std::size_t k = 0; k < v.size(); ++k) s += fmt::format("{}{:.9g}", k ? "," : "", v[k]);
  return s;
}

std::string intervals(const Ways& ways) {
  std::string s;
  for (const auto& way : ways) {
    s += " {";
    for (const Interval& x : way)
      s += x.undefined ? " undefined" : fmt::format(" [{:.9g}, {:.9g}]", x.lo, x.hi);
    s += " }";
  }
  return s;
}

std::string reproduction(Formula f, std::span<const float> in, PrecisionRules rules) {
  if (f != Formula::Reflect && f != Formula::Refract) return "";
  const std::string eta = f == Formula::Refract ? fmt::format(",\"eta\":{:.9g}", in[6]) : "";
  return fmt::format(
      "\n  reproduce: echo '{{\"fn\":\"{}\",\"I\":[{}],\"N\":[{}]{}}}' | snell eval --backend "
      "oracle --rules {}",
      formulaName(f), floats(in.subspan(0, 3)), floats(in.subspan(3, 3)), eta,
      precisionRulesName(rules));
}

void record(Tally& tally, std::string message) {
  ++tally.escapes;
  if (tally.firstEscapes.size() < Tally::kEscapesKept)
    tally.firstEscapes.push_back(std::move(message));
}

// One catalog listing run on the machine: each output's components, by
// name, in the listing's visit order.
using NamedOutputs = std::vector<std::pair<std::string, std::vector<float>>>;
using MachineRun = NamedOutputs (*)(const UniformMap&, const ConstantMap&, const AttributeMap&,
                                    std::size_t vertex);

template <template <class> class Shader>
NamedOutputs runOnMachine(const UniformMap& uniforms, const ConstantMap& constants,
                          const AttributeMap& attributes, std::size_t vertex) {
  Shader<Adv> shader{};
  listings::BindUniforms<Adv> bindUniforms(uniforms, constants);
  shader.visit(bindUniforms);
  listings::BindVertex<Adv> bindVertex(attributes, vertex);
  shader.visit(bindVertex);
  shader.main();
  listings::CollectOutputs<Adv> outputs;
  shader.visit(outputs);
  listings::DescribeInterface describe;
  shader.visit(describe);
  NamedOutputs named;
  std::size_t next = 0;
  for (const listings::InterfaceEntry& e : describe.entries()) {
    if (e.kind != listings::InterfaceEntry::Kind::Output) continue;
    std::vector<float>& values = named.emplace_back(e.name, std::vector<float>{}).second;
    for (int k = 0; k < componentCount(e.type); ++k)
      values.push_back(outputs.values[next++].value());
  }
  return named;
}

// Every output's components, one after the other.
std::vector<float> allOf(const NamedOutputs& outputs) {
  std::vector<float> values;
  for (const auto& [name, components] : outputs)
    values.insert(values.end(), components.begin(), components.end());
  return values;
}

struct MachineListing {
  std::string name;
  MachineRun run;
  bool legacy;  // reads fixed-function state derived from the bound matrices
};

const std::vector<MachineListing>& machineListingTable() {
  static const std::vector<MachineListing> table = [] {
    std::vector<MachineListing> all;
    test::forEachCatalogShader([&]<template <class> class Shader>(const char* name, bool legacy) {
      all.push_back(MachineListing{name, runOnMachine<Shader>, legacy});
    });
    return all;
  }();
  return table;
}

const MachineListing& machineListing(const std::string& name) {
  for (const MachineListing& l : machineListingTable())
    if (name == l.name) return l;
  throw std::invalid_argument("no machine run for listing oracle " + name);
}

bool fitsVarying(const OracleVarying& v, std::size_t vertex, std::span<const float> values) {
  const auto sample = std::find_if(v.alternatives.begin(), v.alternatives.end(),
                                   [&](const SampleAlternatives& s) { return s.sample == vertex; });
  if (sample != v.alternatives.end()) {
    return std::any_of(sample->ways.begin(), sample->ways.end(), [&](const OracleAlternative& w) {
      for (std::size_t k = 0; k < values.size(); ++k)
        if (!w.undefined[k] && !(w.lo[k] <= values[k] && values[k] <= w.hi[k])) return false;
      return true;
    });
  }
  const std::size_t base = vertex * values.size();
  for (std::size_t k = 0; k < values.size(); ++k)
    if (!v.undefined[base + k] && !(v.lo[base + k] <= values[k] && values[k] <= v.hi[base + k]))
      return false;
  return true;
}

std::string describeVarying(const OracleVarying& v, std::size_t vertex) {
  const auto components = static_cast<std::size_t>(v.components);
  std::string s;
  const auto sample = std::find_if(v.alternatives.begin(), v.alternatives.end(),
                                   [&](const SampleAlternatives& a) { return a.sample == vertex; });
  if (sample != v.alternatives.end()) {
    for (const OracleAlternative& w : sample->ways) {
      s += " {";
      for (std::size_t k = 0; k < components; ++k)
        s += w.undefined[k] ? " undefined" : fmt::format(" [{:.9g}, {:.9g}]", w.lo[k], w.hi[k]);
      s += " }";
    }
    return s;
  }
  for (std::size_t k = 0; k < components; ++k) {
    const std::size_t i = vertex * components + k;
    s += v.undefined[i] ? " undefined" : fmt::format(" [{:.9g}, {:.9g}]", v.lo[i], v.hi[i]);
  }
  return s;
}

// One vertex's attributes, as a batch of one sample.
AttributeMap vertexAlone(const AttributeMap& attributes, std::size_t vertex) {
  AttributeMap one;
  for (const auto& [name, stream] : attributes) {
    const auto n = static_cast<std::size_t>(stream.components);
    const auto first = stream.data.begin() + static_cast<std::ptrdiff_t>(vertex * n);
    one.emplace(name,
                AttributeStream{stream.name, stream.components,
                                std::vector<float>(first, first + static_cast<std::ptrdiff_t>(n))});
  }
  return one;
}

// Each output's components, from one machine evaluation of `program` on
// a batch of one vertex.
std::vector<std::vector<float>> machineOutputs(const derived::Program& program,
                                               const UniformMap& uniforms, const AttributeMap& one,
                                               PrecisionRules rules, std::uint64_t seed) {
  Machine::begin(seed, rules);
  derived::detail::Evaluation<Adv> evaluation(program, uniforms, one, 1);
  std::vector<std::vector<float>> values;
  for (const std::vector<Adv>& output : evaluation.run()) {
    values.emplace_back();
    for (const Adv& x : output) values.back().push_back(x.value());
  }
  return values;
}

// The machine's seed for one run on one vertex: apart for every pair.
std::uint64_t vertexRunSeed(std::uint64_t seed, std::size_t vertex, int run) {
  return seed + (vertex * 131 + static_cast<std::uint64_t>(run)) * 0x9e3779b97f4a7c15ULL;
}

std::string vertexInputs(const AttributeMap& attributes, std::size_t vertex) {
  std::string s;
  for (const auto& [name, stream] : attributes) {
    const auto n = static_cast<std::size_t>(stream.components);
    s += fmt::format(" {}=({})", name,
                     floats(std::span<const float>(stream.data).subspan(vertex * n, n)));
  }
  return s;
}

}  // namespace

bool fitsOneWay(const std::vector<std::vector<Interval>>& ways, std::span<const float> values) {
  return std::any_of(ways.begin(), ways.end(), [&](const std::vector<Interval>& way) {
    for (std::size_t k = 0; k < values.size(); ++k)
      if (!way[k].undefined && !contains(way[k], values[k])) return false;
    return true;
  });
}

void Tally::add(const Tally& other) {
  evaluations += other.evaluations;
  components += other.components;
  boundedComponents += other.boundedComponents;
  escapes += other.escapes;
  for (const std::string& e : other.firstEscapes)
    if (firstEscapes.size() < kEscapesKept) firstEscapes.push_back(e);
}

const char* formulaName(Formula f) {
  switch (f) {
    case Formula::Reflect:
      return "reflect";
    case Formula::Refract:
      return "refract";
    case Formula::Normalize:
      return "normalize";
    case Formula::Length:
      return "length";
    case Formula::Dot:
      return "dot";
    case Formula::Pow:
      return "pow";
    case Formula::Exp2:
      return "exp2";
    case Formula::Log2:
      return "log2";
    case Formula::Sqrt:
      return "sqrt";
    case Formula::InverseSqrt:
      return "inversesqrt";
    case Formula::Mix:
      return "mix";
    case Formula::Clamp:
      return "clamp";
    case Formula::Divide:
      return "divide";
    case Formula::MatrixVector:
      return "mat4*vec4";
    case Formula::FresnelRatio:
      return "fresnel-ratio";
  }
  return "?";
}

int formulaInputs(Formula f) {
  switch (f) {
    case Formula::Reflect:
      return 6;
    case Formula::Refract:
      return 7;
    case Formula::Normalize:
    case Formula::Length:
      return 3;
    case Formula::Dot:
      return 8;
    case Formula::Pow:
    case Formula::Divide:
      return 2;
    case Formula::Exp2:
    case Formula::Log2:
    case Formula::Sqrt:
    case Formula::InverseSqrt:
      return 1;
    case Formula::Mix:
    case Formula::FresnelRatio:
      return 7;
    case Formula::Clamp:
      return 3;
    case Formula::MatrixVector:
      return 20;
  }
  return 0;
}

void checkFormula(Formula f, std::span<const float> inputs, PrecisionRules rules, int runs,
                  std::uint64_t seed, Tally& tally) {
  const UsePrecisionRules use(rules);
  std::vector<Interval> args;
  for (float x : inputs) args.push_back(Interval::point(x));
  const Ways ways = oracleWays([&] { return evaluateFormula<Interval>(f, args); });
  // reflect and refract as `snell eval` answers them, by the shortest road
  // (oracle/point_builtins.h for exact inputs): held to the machine too.
  std::optional<BuiltinResult> shipped;
  if (f == Formula::Reflect || f == Formula::Refract) {
    BuiltinCall call{formulaName(f),
                     {inputs.begin(), inputs.begin() + 3},
                     {inputs.begin() + 3, inputs.begin() + 6}};
    if (f == Formula::Refract) call.eta = inputs[6];
    shipped = evaluateBuiltin(call, rules);
  }
  for (int run = 0; run < runs; ++run) {
    const std::uint64_t runSeed = seed + static_cast<std::uint64_t>(run) * 0x9e3779b97f4a7c15ULL;
    Machine::begin(runSeed, rules);
    std::vector<Adv> machineArgs;
    for (float x : inputs) machineArgs.emplace_back(x);
    const std::vector<Adv> out = evaluateFormula<Adv>(f, machineArgs);
    std::vector<float> values;
    for (const Adv& x : out) values.push_back(x.value());
    ++tally.evaluations;
    if (fitsOneWay(ways, values) && (!shipped || shipped->allows(values))) continue;
    record(tally,
           fmt::format("{} ({} rules) of ({}): machine gave ({}) with seed {:#x}; allowed:{}{}{}",
                       formulaName(f), precisionRulesName(rules), floats(inputs), floats(values),
                       runSeed, intervals(ways),
                       fitsOneWay(ways, values) ? " (eval's answer does not allow it)" : "",
                       reproduction(f, inputs, rules)));
  }
}

std::vector<std::string> machineListings() {
  std::vector<std::string> names;
  for (const MachineListing& l : machineListingTable()) names.push_back(l.name);
  return names;
}

void checkListing(const ListingInputs& in, PrecisionRules rules, int runs, std::uint64_t seed,
                  Tally& tally) {
  const MachineListing& listing = machineListing(in.oracle);
  const std::vector<OracleVarying> varyings = makeVertexOracle(in.oracle)->evaluate(
      {in.uniforms, in.constants, in.attributes, in.vertexCount, rules});
  const UniformMap uniforms = listing.legacy ? withDerivedLegacyState(in.uniforms) : in.uniforms;
  const UsePrecisionRules use(rules);
  for (std::size_t vertex = 0; vertex < in.vertexCount; ++vertex) {
    for (int run = 0; run < runs; ++run) {
      const std::uint64_t runSeed = vertexRunSeed(seed, vertex, run);
      Machine::begin(runSeed, rules);
      const std::vector<float> values =
          allOf(listing.run(uniforms, in.constants, in.attributes, vertex));
      ++tally.evaluations;
      std::size_t offset = 0;
      for (const OracleVarying& v : varyings) {
        const auto n = static_cast<std::size_t>(v.components);
        const std::span<const float> mine = std::span<const float>(values).subspan(offset, n);
        offset += n;
        if (fitsVarying(v, vertex, mine)) continue;
        record(tally, fmt::format("{} ({} rules) {} at vertex{}: machine gave ({}) with seed "
                                  "{:#x}; allowed:{}",
                                  in.oracle, precisionRulesName(rules), v.name,
                                  vertexInputs(in.attributes, vertex), floats(mine), runSeed,
                                  describeVarying(v, vertex)));
      }
    }
  }
}

std::vector<float> derivedOnMachine(const DerivedListingInputs& in, std::size_t vertex,
                                    PrecisionRules rules, std::uint64_t seed) {
  const derived::ApiPrograms programs = derived::lowerForEachApi(in.source, in.outputs);
  const derived::Program& program = programs.forRules(rules);
  const UsePrecisionRules use(rules);
  std::vector<float> values;
  for (const std::vector<float>& output :
       machineOutputs(program, derived::withLegacyState(program, in.bindings.uniforms),
                      vertexAlone(in.bindings.attributes, vertex), rules, seed))
    values.insert(values.end(), output.begin(), output.end());
  return values;
}

void checkDerivedListing(const DerivedListingInputs& in, PrecisionRules rules, int runs,
                         std::uint64_t seed, Tally& tally) {
  checkDerivedListing(in, in.source, rules, runs, seed, tally);
}

void checkDerivedListing(const DerivedListingInputs& in, const derived::ShaderSource& machineSource,
                         PrecisionRules rules, int runs, std::uint64_t seed, Tally& tally) {
  const ListingInputs& b = in.bindings;
  const std::vector<OracleVarying> varyings =
      derived::makeDerivedVectorOracle(in.source, in.outputs)
          ->evaluate({b.uniforms, b.constants, b.attributes, b.vertexCount, rules});
  // The program the derived oracle evaluates under these rules, of the
  // machine's text.
  const derived::ApiPrograms programs = derived::lowerForEachApi(machineSource, in.outputs);
  const derived::Program& program = programs.forRules(rules);
  const UniformMap uniforms = derived::withLegacyState(program, b.uniforms);
  const UsePrecisionRules use(rules);
  for (std::size_t vertex = 0; vertex < b.vertexCount; ++vertex) {
    const AttributeMap one = vertexAlone(b.attributes, vertex);
    for (int run = 0; run < runs; ++run) {
      const std::uint64_t runSeed = vertexRunSeed(seed, vertex, run);
      const std::vector<std::vector<float>> outputs =
          machineOutputs(program, uniforms, one, rules, runSeed);
      ++tally.evaluations;
      if (outputs.size() != varyings.size())
        throw std::logic_error(in.source.file + ": the machine's program and the oracle's differ");
      for (std::size_t k = 0; k < outputs.size(); ++k) {
        const std::vector<float>& mine = outputs[k];
        const OracleVarying& v = varyings[k];
        const auto components = static_cast<std::size_t>(v.components);
        if (mine.size() != components)
          throw std::logic_error(
              fmt::format("{}: the machine's {} has {} components, the oracle's {}", in.source.file,
                          v.name, mine.size(), components));
        // What the check holds: the components the oracle bounds.
        tally.components += components;
        for (std::size_t i = 0; i < components; ++i)
          if (!v.undefined[vertex * components + i]) ++tally.boundedComponents;
        if (fitsVarying(v, vertex, mine)) continue;
        record(tally, fmt::format("{} (derived, {} rules) {} at vertex{}: machine gave ({}) with "
                                  "seed {:#x}; allowed:{}",
                                  in.source.file, precisionRulesName(rules), v.name,
                                  vertexInputs(b.attributes, vertex), floats(mine), runSeed,
                                  describeVarying(v, vertex)));
      }
    }
  }
}

void checkHandWrittenAgainstDerived(const DerivedListingInputs& in, PrecisionRules rules, int runs,
                                    std::uint64_t seed, Tally& tally) {
  if (in.handWritten.empty()) return;
  const ListingInputs& b = in.bindings;
  const std::vector<OracleVarying> varyings =
      derived::makeDerivedVectorOracle(in.source, in.outputs)
          ->evaluate({b.uniforms, b.constants, b.attributes, b.vertexCount, rules});
  const MachineListing& listing = machineListing(in.handWritten);
  const UniformMap uniforms = listing.legacy ? withDerivedLegacyState(b.uniforms) : b.uniforms;
  const UsePrecisionRules use(rules);
  for (std::size_t vertex = 0; vertex < b.vertexCount; ++vertex) {
    for (int run = 0; run < runs; ++run) {
      const std::uint64_t runSeed = vertexRunSeed(seed, vertex, run);
      Machine::begin(runSeed, rules);
      const NamedOutputs outputs = listing.run(uniforms, b.constants, b.attributes, vertex);
      ++tally.evaluations;
      for (const OracleVarying& v : varyings) {
        // A capture the hand-written listing names otherwise (or keeps as
        // a local) is not compared.
        const auto mine = std::find_if(outputs.begin(), outputs.end(),
                                       [&](const auto& output) { return output.first == v.name; });
        if (mine == outputs.end()) continue;
        const auto components = static_cast<std::size_t>(v.components);
        if (mine->second.size() != components)
          throw std::logic_error(fmt::format("{}: {} has {} components in {}, {} derived",
                                             in.source.file, v.name, mine->second.size(),
                                             in.handWritten, components));
        tally.components += components;
        for (std::size_t i = 0; i < components; ++i)
          if (!v.undefined[vertex * components + i]) ++tally.boundedComponents;
        if (fitsVarying(v, vertex, mine->second)) continue;
        record(tally, fmt::format("{} (hand-written {} on the machine, derived oracle, {} rules) "
                                  "{} at vertex{}: machine gave ({}) with seed {:#x}; allowed:{}",
                                  in.source.file, in.handWritten, precisionRulesName(rules), v.name,
                                  vertexInputs(b.attributes, vertex), floats(mine->second), runSeed,
                                  describeVarying(v, vertex)));
      }
    }
  }
}

}  // namespace snell::adversary
