#pragma once
// A worker's oracle results: computed once per case and API and shared by
// its checks, and kept across runs in the oracle store when there is one.
#include <map>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "core/case.h"
#include "core/expected_values.h"
#include "runner/listing_oracles.h"
#include "runner/oracle_store/oracle_store.h"

namespace snell {

class OracleCache {
 public:
  OracleCache() = default;
  // Reads and keeps results in `store` as well, across runs.
  explicit OracleCache(std::optional<OracleStore> store) : store_(std::move(store)) {}

  // `oracle` on `input`: read from the store when an earlier run computed
  // it, else computed (and stored).
  std::vector<OracleVarying> evaluate(const NamedOracle& oracle, const OracleInput& input);
  // Results given by evaluate(), and how many of them came from the store.
  int evaluated() const { return evaluated_; }
  int stored() const { return stored_; }

  // Evaluates on first use. Throws UsageError when the manifest captures an
  // output the oracle does not compute.
  // Intervals follow `rules`, the API of the backend they judge.
  const std::vector<OracleVarying>& get(const Case& c, const NamedOracle& oracle,
                                        const ResolvedBindings& bindings, PrecisionRules rules,
                                        double* secondsSpent);

 private:
  // By case id and oracle label.
  std::map<std::tuple<std::string, std::string, PrecisionRules>, std::vector<OracleVarying>>
      results_;
  std::optional<OracleStore> store_;
  int evaluated_ = 0;
  int stored_ = 0;
};

}  // namespace snell
