#include "runner/case_result_json.h"

#include "runner/checks/check_kind.h"
#include "runner/json_fields.h"

namespace snell {
namespace {

Status statusOf(const std::string& name) {
  if (const std::optional<Status> status = statusFromName(name)) return *status;
  throw nlohmann::json::other_error::create(501, "unknown status " + name, nullptr);
}

nlohmann::json phasesJson(const PhaseTimes& phases) {
  nlohmann::json out = nlohmann::json::object();
  for (Phase p : kAllPhases) out[std::string(phaseName(p))] = phases[p];
  return out;
}

// Absent from records written before phases were timed: all zero then.
PhaseTimes phasesFromJson(const nlohmann::json& record) {
  PhaseTimes phases;
  if (!record.contains("phases")) return phases;
  const nlohmann::json& j = record.at("phases");
  if (!j.is_object()) throw nlohmann::json::type_error::create(302, "phases must be an object", &j);
  for (Phase p : kAllPhases)
    if (j.contains(std::string(phaseName(p))))
      phases[p] = j.at(std::string(phaseName(p))).get<double>();
  return phases;
}

}  // namespace

nlohmann::json toJson(const CaseResult& r) {
  nlohmann::json reruns = nlohmann::json::array();
  for (Status s : r.reruns) reruns.push_back(statusName(s));
  nlohmann::json record = {{"case", r.caseId},
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
                           {"compile_log", r.compileLog},
                           {"seconds", r.seconds},
                           {"backend_seconds", r.backendSeconds},
                           {"oracle_seconds", r.oracleSeconds},
                           {"oracle_results", r.oracleResults},
                           {"oracle_stored", r.oracleStored},
                           {"phases", phasesJson(r.phases)},
                           {"reruns", reruns}};
  if (!r.shard.empty()) record["shard"] = r.shard;
  for (const auto& kind : checkKinds()) kind->writeJson(r, record);
  return record;
}

CaseResult caseResultFromJson(const nlohmann::json& j) {
  CaseResult r;
  r.caseId = j.at("case").get<std::string>();
  r.backend = j.at("backend").get<std::string>();
  r.status = statusOf(j.at("status").get<std::string>());
  r.message = j.at("message").get<std::string>();
  r.title = j.at("title").get<std::string>();
  r.sourceFile = j.at("source").at("file").get<std::string>();
  r.sourceWhere = j.at("source").at("where").get<std::string>();
  const nlohmann::json& d = j.at("driver");
  r.driver = {d.at("api").get<std::string>(), d.at("api_version").get<std::string>(),
              d.at("renderer").get<std::string>(), d.at("driver_version").get<std::string>(),
              d.at("device_type").get<std::string>()};
  r.vertices = jsonCount<std::size_t>(j.at("vertices"));
  for (const auto& kind : checkKinds()) kind->readJson(j, r);
  r.compileLog = j.at("compile_log").get<std::string>();
  r.seconds = j.at("seconds").get<double>();
  r.backendSeconds = j.at("backend_seconds").get<double>();
  r.oracleSeconds = j.at("oracle_seconds").get<double>();
  r.phases = phasesFromJson(j);
  // Absent from records written before results were stored.
  if (j.contains("oracle_results")) r.oracleResults = jsonCount<int>(j.at("oracle_results"));
  if (j.contains("oracle_stored")) r.oracleStored = jsonCount<int>(j.at("oracle_stored"));
  if (j.contains("shard")) r.shard = j.at("shard").get<std::string>();
  // Absent from records written before reruns existed.
  if (j.contains("reruns"))
    for (const nlohmann::json& s : j.at("reruns"))
      r.reruns.push_back(statusOf(s.get<std::string>()));
  return r;
}

}  // namespace snell
