#pragma once
// "image": the listing rendered into an RGBA32F target and held against the
// CPU reference (correct?) and the golden (changed?); the comparison with
// every other backend that ran the case is made after the run
// (runner/cross_api_check.h) and lands in the same result.
#include "runner/checks/check_kind.h"

namespace snell {

class ImageCheckKind : public CheckKind {
 public:
  std::string name() const override { return "image"; }
  void validate(const Case& c, const ProgramSource& program, const Scene& scene) const override;
  void run(const Case& c, const ResolvedBindings& bindings, CheckEnvironment& environment,
           CaseResult& result) const override;
  void writeJson(const CaseResult& result, nlohmann::json& record) const override;
  void readJson(const nlohmann::json& record, CaseResult& result) const override;
  std::vector<SummaryColumn> summaryColumns() const override;
  std::string junitMessage(const CaseResult& result) const override;
};

}  // namespace snell
