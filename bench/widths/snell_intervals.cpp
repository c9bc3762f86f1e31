#include "widths/snell_intervals.h"

#include "oracle/builtin_probe.h"
#include "oracle/vertex_oracle.h"

namespace snell::widths {

namespace {
bool fits(const SnellWay& way, const std::vector<float>& vector) {
  for (std::size_t k = 0; k < vector.size(); ++k) {
    if (way.undefined[k]) continue;
    if (!(vector[k] >= way.lo[k] && vector[k] <= way.hi[k])) return false;
  }
  return true;
}
}  // namespace

bool SnellSample::allows(const std::vector<float>& vector) const {
  for (const SnellWay& way : ways)
    if (fits(way, vector)) return true;
  return false;
}

SnellSample snellBuiltin(const std::string& fn, const std::vector<float>& I,
                         const std::vector<float>& N, float eta, PrecisionRules rules) {
  const BuiltinResult result = evaluateBuiltin(BuiltinCall{fn, I, N, eta}, rules);
  SnellSample sample;
  sample.hull = SnellWay{result.lo, result.hi, result.undefined};
  for (const BuiltinWay& way : result.ways)
    sample.ways.push_back(SnellWay{way.lo, way.hi, way.undefined});
  if (sample.ways.empty()) sample.ways.push_back(sample.hull);
  return sample;
}

std::vector<std::vector<SnellSample>> snellListing(const std::string& oracle,
                                                   const ListingBindings& bindings,
                                                   PrecisionRules rules) {
  const std::vector<OracleVarying> varyings = makeVertexOracle(oracle)->evaluate(
      {bindings.uniforms, bindings.constants, bindings.attributes, bindings.vertexCount, rules});
  std::vector<std::vector<SnellSample>> samples;
  for (const OracleVarying& varying : varyings) {
    const auto components = static_cast<std::size_t>(varying.components);
    std::vector<SnellSample> perVertex(bindings.vertexCount);
    for (std::size_t vertex = 0; vertex < bindings.vertexCount; ++vertex) {
      SnellWay& hull = perVertex[vertex].hull;
      for (std::size_t c = 0; c < components; ++c) {
        const std::size_t i = vertex * components + c;
        hull.lo.push_back(varying.lo[i]);
        hull.hi.push_back(varying.hi[i]);
        hull.undefined.push_back(varying.undefined[i] != 0);
      }
    }
    for (const SampleAlternatives& alternatives : varying.alternatives)
      for (const OracleAlternative& way : alternatives.ways) {
        SnellWay w{way.lo, way.hi, {}};
        for (std::uint8_t u : way.undefined) w.undefined.push_back(u != 0);
        perVertex[alternatives.sample].ways.push_back(std::move(w));
      }
    for (SnellSample& sample : perVertex)
      if (sample.ways.empty()) sample.ways.push_back(sample.hull);
    samples.push_back(std::move(perVertex));
  }
  return samples;
}

std::vector<std::string> snellListingOutputs(const std::string& oracle) {
  return makeVertexOracle(oracle)->outputs();
}

const char* snellOracleVersion() { return "this branch"; }

}  // namespace snell::widths
