#include "runner/oracle_cache.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "core/phase_clock.h"
#include "runner/oracle_store/oracle_store_key.h"
#include "runner/run_helpers.h"

namespace snell {

const std::vector<OracleVarying>& OracleCache::get(const Case& c, const NamedOracle& named,
                                                   const ResolvedBindings& bindings,
                                                   PrecisionRules rules, double* secondsSpent) {
  *secondsSpent = 0;
  const std::tuple key{c.id, named.label, rules};
  if (auto it = results_.find(key); it != results_.end()) return it->second;
  const PhaseScope phase(Phase::Oracle);
  const auto start = std::chrono::steady_clock::now();
  const Manifest& m = *c.manifest;
  const VertexOracle* oracle = named.oracle.get();
  const std::vector<std::string> outputs = oracle->outputs();
  for (const std::string& name : m.captureVertex)
    if (std::find(outputs.begin(), outputs.end(), name) == outputs.end())
      throw std::logic_error(
          fmt::format("{}: `{}` is not computed by oracle `{}`: "
                      "validateCase lets no such manifest through",
                      m.path.string(), name, named.label));
  std::vector<OracleVarying> all = evaluate(
      named, {bindings.uniforms, m.constants, bindings.attributes, bindings.vertexCount, rules});
  std::vector<OracleVarying> captured;
  for (const std::string& name : m.captureVertex)
    for (OracleVarying& v : all)
      if (v.name == name) captured.push_back(std::move(v));
  *secondsSpent = secondsSince(start);
  return results_.emplace(key, std::move(captured)).first->second;
}

std::vector<OracleVarying> OracleCache::evaluate(const NamedOracle& oracle,
                                                 const OracleInput& input) {
  ++evaluated_;
  if (!store_ || oracle.identity.empty()) return oracle.oracle->evaluate(input);
  const Digest key = oracleResultKey(oracle.identity, input);
  if (std::optional<std::vector<OracleVarying>> kept = store_->load(key)) {
    ++stored_;
    return std::move(*kept);
  }
  std::vector<OracleVarying> result = oracle.oracle->evaluate(input);
  store_->save(key, result);
  return result;
}

}  // namespace snell
