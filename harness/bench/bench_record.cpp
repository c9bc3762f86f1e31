#include "bench/bench_record.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "core/atomic_file.h"
#include "core/errors.h"
#include "runner/json_fields.h"

namespace snell::bench {
namespace {

using nlohmann::json;

json errorJson(const ImageError& e) {
  return {{"rms", e.rms},
          {"max", e.max},
          {"de_mean", e.deMean},
          {"de_p95", e.deP95},
          {"compared_pixels", e.compared}};
}

json timingJson(const FrameTiming& t) {
  return {{"width", t.width},        {"height", t.height}, {"repeats", t.repeats},
          {"median_ms", t.medianMs}, {"min_ms", t.minMs},  {"max_ms", t.maxMs},
          {"p10_ms", t.p10Ms},       {"p90_ms", t.p90Ms}};
}

FrameTiming timingFromJson(const json& t) {
  return {t.at("width").get<int>(),        t.at("height").get<int>(), t.value("repeats", 0),
          t.at("median_ms").get<double>(), t.value("min_ms", 0.0),    t.value("max_ms", 0.0),
          t.value("p10_ms", 0.0),          t.value("p90_ms", 0.0)};
}

json toJson(const BenchRecord& r) {
  json byAngle = json::array();
  for (const AngleBin& bin : r.errorByAngle) {
    json entry = errorJson(bin.error);
    entry["from_deg"] = bin.fromDeg;
    entry["to_deg"] = bin.toDeg;
    byAngle.push_back(entry);
  }
  json timings = json::array();
  for (const FrameTiming& t : r.timings) timings.push_back(timingJson(t));
  json byTessellation = json::array();
  for (const TessellationTiming& t : r.byTessellation) {
    json entry = timingJson(t.timing);
    entry["stacks"] = t.stacks;
    entry["slices"] = t.slices;
    entry["vertices"] = t.vertices;
    entry["triangles"] = t.triangles;
    byTessellation.push_back(entry);
  }
  return {{"method", r.method},
          {"title", r.title},
          {"backend", r.backend},
          {"renderer", r.renderer},
          {"parameters", r.parameters},
          {"ms_per_frame", r.msPerFrame()},
          {"timings", timings},
          {"timings_by_tessellation", byTessellation},
          {"error",
           {{"width", r.errorWidth},
            {"rms", r.error.rms},
            {"max", r.error.max},
            {"de_mean", r.error.deMean},
            {"de_p95", r.error.deP95},
            {"compared_pixels", r.error.compared},
            {"coverage_mismatch_pixels", r.error.coverageMismatch}}},
          {"error_by_angle", byAngle}};
}

BenchRecord fromJson(const json& j) {
  BenchRecord r;
  r.method = j.at("method").get<std::string>();
  r.title = j.value("title", "");
  r.backend = j.at("backend").get<std::string>();
  r.renderer = j.value("renderer", "");
  if (j.contains("parameters"))
    r.parameters = j.at("parameters").get<std::map<std::string, double>>();
  for (const json& t : j.at("timings")) r.timings.push_back(timingFromJson(t));
  for (const json& t : j.value("timings_by_tessellation", json::array()))
    r.byTessellation.push_back({t.at("stacks").get<int>(), t.at("slices").get<int>(),
                                t.at("vertices").get<std::size_t>(),
                                t.value("triangles", std::size_t{0}), timingFromJson(t)});
  if (r.timings.empty()) throw std::invalid_argument("a record has no timings");
  const json& e = j.at("error");
  r.errorWidth = e.value("width", 0);
  r.error.rms = e.at("rms").get<double>();
  r.error.max = e.at("max").get<double>();
  r.error.deMean = e.at("de_mean").get<double>();
  r.error.deP95 = e.at("de_p95").get<double>();
  r.error.compared = e.value("compared_pixels", std::size_t{0});
  r.error.coverageMismatch = e.value("coverage_mismatch_pixels", std::size_t{0});
  // An error is a distance: a negative or non-finite one is no measurement,
  // and would be chosen as the most accurate.
  for (const double value : {r.error.rms, r.error.max, r.error.deMean, r.error.deP95})
    if (!(value >= 0.0 && std::isfinite(value)))
      throw std::invalid_argument(
          fmt::format("{} on {} has an error of {}; errors are finite "
                      "and 0 or more",
                      r.method, r.backend, value));
  for (const json& bin : j.value("error_by_angle", json::array())) {
    AngleBin b{bin.at("from_deg").get<double>(), bin.at("to_deg").get<double>(), {}};
    b.error.rms = bin.at("rms").get<double>();
    b.error.max = bin.at("max").get<double>();
    b.error.deMean = bin.at("de_mean").get<double>();
    b.error.deP95 = bin.at("de_p95").get<double>();
    b.error.compared = bin.value("compared_pixels", std::size_t{0});
    r.errorByAngle.push_back(b);
  }
  return r;
}

}  // namespace

const std::vector<std::string>& errorMetricNames() {
  static const std::vector<std::string> names{"rms", "max", "de_mean", "de_p95"};
  return names;
}

double errorMetric(const ImageError& error, const std::string& metric) {
  if (metric == "rms") return error.rms;
  if (metric == "max") return error.max;
  if (metric == "de_mean") return error.deMean;
  if (metric == "de_p95") return error.deP95;
  throw UsageError(fmt::format("unknown error metric `{}`; use one of {}", metric,
                               fmt::join(errorMetricNames(), ", ")));
}

void writeBenchResults(const BenchResults& results, const std::filesystem::path& path) {
  json records = json::array();
  for (const BenchRecord& r : results.records) records.push_back(toJson(r));
  const json doc{{"scene", results.scene}, {"reference", results.reference}, {"records", records}};
  writeFileAtomically(path, jsonText(doc, 2) + "\n");
}

BenchResults readBenchResults(const std::filesystem::path& path) {
  if (std::filesystem::is_directory(path))
    throw UsageError(
        fmt::format("{}: is a folder; give --results the bench.json in it", path.string()));
  std::ifstream in(path);
  if (!in)
    throw UsageError(
        fmt::format("{}: cannot read bench results; run `snell bench` first or give "
                    "--results FILE",
                    path.string()));
  try {
    const json doc = json::parse(in);
    if (!doc.is_object())
      throw std::invalid_argument(
          fmt::format("it is a JSON {}, where bench.json is an object with `scene` and `records`",
                      doc.type_name()));
    BenchResults results;
    results.scene = doc.at("scene").get<std::string>();
    results.reference = doc.value("reference", "");
    for (const json& r : doc.at("records")) {
      BenchRecord record = fromJson(r);
      // Twice, a method would be its own runner-up.
      for (const BenchRecord& earlier : results.records)
        if (earlier.method == record.method && earlier.backend == record.backend)
          throw std::invalid_argument(
              fmt::format("{} on {} is measured twice", record.method, record.backend));
      results.records.push_back(std::move(record));
    }
    if (results.records.empty()) throw std::invalid_argument("it holds no measurement");
    return results;
  } catch (const std::exception& error) {
    throw UsageError(
        fmt::format("{}: not a `snell bench` results file ({}); run `snell bench` "
                    "to write one",
                    path.string(), readableError(error)));
  }
}

}  // namespace snell::bench
