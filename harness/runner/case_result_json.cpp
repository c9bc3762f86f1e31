#include "runner/case_result_json.h"

#include <cmath>
#include <limits>

namespace snell {
namespace {

// JSON has no infinity: a slack past every bound is written as null.
nlohmann::json number(double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(); }

double numberOr(const nlohmann::json& x, double infinite) {
  return x.is_null() ? infinite : x.get<double>();
}

Status statusFromName(const std::string& name) {
  for (int k = 0; k <= static_cast<int>(Status::Crash); ++k)
    if (name == statusName(static_cast<Status>(k))) return static_cast<Status>(k);
  throw nlohmann::json::other_error::create(501, "unknown status " + name, nullptr);
}

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

CaseResult caseResultFromJson(const nlohmann::json& j) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  CaseResult r;
  r.caseId = j.at("case").get<std::string>();
  r.backend = j.at("backend").get<std::string>();
  r.status = statusFromName(j.at("status").get<std::string>());
  r.message = j.at("message").get<std::string>();
  r.title = j.at("title").get<std::string>();
  r.sourceFile = j.at("source").at("file").get<std::string>();
  r.sourceWhere = j.at("source").at("where").get<std::string>();
  const nlohmann::json& d = j.at("driver");
  r.driver = {d.at("api").get<std::string>(), d.at("api_version").get<std::string>(),
              d.at("renderer").get<std::string>(), d.at("driver_version").get<std::string>(),
              d.at("device_type").get<std::string>()};
  r.vertices = j.at("vertices").get<std::size_t>();
  for (const nlohmann::json& v : j.at("varyings")) {
    VaryingCheck check;
    check.name = v.at("name").get<std::string>();
    check.checked = v.at("checked").get<std::size_t>();
    check.undefined = v.at("undefined").get<std::size_t>();
    check.failed = v.at("failed").get<std::size_t>();
    check.worstSlack = numberOr(v.at("worst_slack"), kInf);
    check.worstVertex = v.at("worst_vertex").get<std::size_t>();
    for (const nlohmann::json& f : v.at("first_failures"))
      check.firstFailures.push_back(
          {f.at("vertex").get<std::size_t>(), f.at("component").get<int>(),
           static_cast<float>(numberOr(f.at("observed"), std::nan(""))), f.at("reference").get<double>(),
           f.at("lo").get<double>(), f.at("hi").get<double>(), numberOr(f.at("slack"), kInf)});
    r.varyings.push_back(std::move(check));
  }
  r.compileLog = j.at("compile_log").get<std::string>();
  r.seconds = j.at("seconds").get<double>();
  r.backendSeconds = j.at("backend_seconds").get<double>();
  r.oracleSeconds = j.at("oracle_seconds").get<double>();
  return r;
}

}  // namespace snell
