#include "runner/case_result_json.h"

#include "core/errors.h"
#include "runner/checks/check_kind.h"
#include "runner/json_fields.h"

namespace snell {
namespace {

// The record's field `key` as T: a field that is missing or of another
// type names itself (the JSON library's message alone, "type must be
// number, but is string", left the reader to guess which).
template <class T>
T field(const nlohmann::json& j, const char* key) {
  try {
    return j.at(key).get<T>();
  } catch (const nlohmann::json::exception& error) {
    throw nlohmann::json::other_error::create(
        501, std::string("\"") + key + "\": " + readableError(error), &j);
  }
}

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
  if (!r.shardOf.empty()) record["shard_of"] = r.shardOf;
  if (!r.shardCases.empty()) record["shard_cases"] = r.shardCases;
  if (!r.listingDigest.empty()) record["listing_digest"] = r.listingDigest;
  for (const auto& kind : checkKinds()) kind->writeJson(r, record);
  return record;
}

CaseResult caseResultFromJson(const nlohmann::json& j) {
  if (!j.is_object())
    throw nlohmann::json::type_error::create(
        302, std::string("a record is an object, not ") + j.type_name(), &j);
  CaseResult r;
  r.caseId = field<std::string>(j, "case");
  r.backend = field<std::string>(j, "backend");
  r.status = statusOf(field<std::string>(j, "status"));
  r.message = field<std::string>(j, "message");
  r.title = field<std::string>(j, "title");
  const auto source = field<nlohmann::json>(j, "source");
  r.sourceFile = field<std::string>(source, "file");
  r.sourceWhere = field<std::string>(source, "where");
  const auto d = field<nlohmann::json>(j, "driver");
  r.driver = {field<std::string>(d, "api"), field<std::string>(d, "api_version"),
              field<std::string>(d, "renderer"), field<std::string>(d, "driver_version"),
              field<std::string>(d, "device_type")};
  r.vertices = jsonCount<std::size_t>(field<nlohmann::json>(j, "vertices"));
  for (const auto& kind : checkKinds()) kind->readJson(j, r);
  r.compileLog = field<std::string>(j, "compile_log");
  r.seconds = field<double>(j, "seconds");
  r.backendSeconds = field<double>(j, "backend_seconds");
  r.oracleSeconds = field<double>(j, "oracle_seconds");
  r.phases = phasesFromJson(j);
  // Absent from records written before results were stored.
  if (j.contains("oracle_results")) r.oracleResults = jsonCount<int>(j.at("oracle_results"));
  if (j.contains("oracle_stored")) r.oracleStored = jsonCount<int>(j.at("oracle_stored"));
  if (j.contains("shard")) r.shard = field<std::string>(j, "shard");
  // Absent from records written before shards named their selection.
  if (j.contains("shard_of")) r.shardOf = field<std::string>(j, "shard_of");
  // Absent from records written before records carried it.
  if (j.contains("listing_digest")) r.listingDigest = field<std::string>(j, "listing_digest");
  // Absent from records written before shards counted each other's cases.
  if (j.contains("shard_cases")) {
    const nlohmann::json& counts = j.at("shard_cases");
    if (!counts.is_array())
      throw nlohmann::json::type_error::create(302, "\"shard_cases\" must be an array of counts",
                                               &counts);
    for (const nlohmann::json& count : counts)
      r.shardCases.push_back(jsonCount<std::size_t>(count));
  }
  // Absent from records written before reruns existed.
  if (j.contains("reruns"))
    for (const nlohmann::json& s : j.at("reruns"))
      r.reruns.push_back(statusOf(s.get<std::string>()));
  return r;
}

}  // namespace snell
