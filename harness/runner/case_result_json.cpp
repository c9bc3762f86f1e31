#include "report/json_results.h"

#include <cmath>

namespace snell {
namespace {

// JSON has no infinity: a slack past every bound is written as null.
nlohmann::json number(double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(); }

}  // namespace

nlohmann::json toJson(const CaseResult& r) {
  nlohmann::json varyings = nlohmann::json::array();
  for (const VaryingCheck& v : r.varyings) {
    nlohmann::json failures = nlohmann::json::array();
    for (const ComponentFailure& f : v.firstFailures)
      failures.push_back({{"vertex", f.vertex}, {"component", f.component},
                          {"observed", number(f.observed)}, {"reference", f.reference},
                          {"lo", f.lo}, {"hi", f.hi}, {"slack", number(f.slack)}});
    varyings.push_back({{"name", v.name},
                        {"checked", v.checked},
                        {"undefined", v.undefined},
                        {"failed", v.failed},
                        {"worst_slack", number(v.worstSlack)},
                        {"worst_vertex", v.worstVertex},
                        {"first_failures", failures}});
  }
  return {{"case", r.caseId},
          {"backend", r.backend},
          {"status", statusName(r.status)},
          {"message", r.message},
          {"title", r.title},
          {"source", {{"file", r.sourceFile}, {"where", r.sourceWhere}}},
          {"driver",
           {{"api", r.driver.api},
            {"api_version", r.driver.apiVersion},
            {"renderer", r.driver.renderer},
            {"driver_version", r.driver.driverVersion},
            {"device_type", r.driver.deviceType}}},
          {"vertices", r.vertices},
          {"components_checked", r.componentsChecked()},
          {"components_undefined", r.componentsUndefined()},
          {"components_failed", r.componentsFailed()},
          {"worst_slack", number(r.worstSlack())},
          {"varyings", varyings},
          {"compile_log", r.compileLog},
          {"seconds", r.seconds},
          {"backend_seconds", r.backendSeconds},
          {"oracle_seconds", r.oracleSeconds}};
}

}  // namespace snell
