#pragma once
// "vectors": the listing's outputs read back (vertex outputs by transform
// feedback, fragment values through probes) and every component held
// against the interval the oracle gives under the backend's precision rules.
#include "runner/checks/check_kind.h"

namespace snell {

class VectorCheckKind : public CheckKind {
 public:
  std::string name() const override { return "vectors"; }
  void validate(const Case& c, const ProgramSource& program, const Scene& scene) const override;
  void run(const Case& c, const ResolvedBindings& bindings, CheckEnvironment& environment,
           CaseResult& result) const override;
  void writeJson(const CaseResult& result, nlohmann::json& record) const override;
  void readJson(const nlohmann::json& record, CaseResult& result) const override;
  std::vector<SummaryColumn> summaryColumns() const override;
  std::string junitMessage(const CaseResult& result) const override;
};

}  // namespace snell
