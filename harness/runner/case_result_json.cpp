#include "runner/case_result_json.h"

#include <cmath>
#include <cstdint>
#include <limits>

namespace snell {
namespace {

// JSON has no infinity: a slack past every bound is written as null.
nlohmann::json number(double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(); }

double numberOr(const nlohmann::json& x, double infinite) {
  return x.is_null() ? infinite : x.get<double>();
}

// nlohmann's get<std::size_t>() on 1e20 or -2.5 is a float-to-integer cast
// with undefined behaviour; a record from a worker or a file is checked first.
template <class Integer>
Integer count(const nlohmann::json& x) {
  if (!x.is_number_integer() && !x.is_number_unsigned())
    throw nlohmann::json::type_error::create(302, "expected an integer, got " + x.dump(), &x);
  if (x.is_number_unsigned()) {
    const auto value = x.get<std::uint64_t>();
    if (value > static_cast<std::uint64_t>(std::numeric_limits<Integer>::max()))
      throw nlohmann::json::type_error::create(302, "integer out of range: " + x.dump(), &x);
    return static_cast<Integer>(value);
  }
  const auto value = x.get<std::int64_t>();
  if (value < static_cast<std::int64_t>(std::numeric_limits<Integer>::min()) ||
      (value > 0 && static_cast<std::uint64_t>(value) > static_cast<std::uint64_t>(std::numeric_limits<Integer>::max())))
    throw nlohmann::json::type_error::create(302, "integer out of range: " + x.dump(), &x);
  return static_cast<Integer>(value);
}

Status statusOf(const std::string& name) {
  if (const std::optional<Status> status = statusFromName(name)) return *status;
  throw nlohmann::json::other_error::create(501, "unknown status " + name, nullptr);
}

nlohmann::json imageToJson(const ImageComparison& c) {
  return {{"against", c.against},        {"verdict", imageVerdictName(c.verdict)},
          {"max_error", number(c.maxError)}, {"mean_error", number(c.meanError)},
          {"rms_error", number(c.rmsError)}, {"psnr", number(c.psnr)},
          {"max_x", c.maxX},             {"max_y", c.maxY},
          {"compared", c.compared},      {"failed", c.failed},
          {"warned", c.warned},          {"masked", c.masked},
          {"problem", c.problem}};
}

ImageVerdict verdictFromName(const std::string& name) {
  for (ImageVerdict v : {ImageVerdict::Pass, ImageVerdict::Warn, ImageVerdict::Fail})
    if (name == imageVerdictName(v)) return v;
  throw nlohmann::json::other_error::create(501, "unknown image verdict " + name, nullptr);
}

ImageComparison imageFromJson(const nlohmann::json& j) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  ImageComparison c;
  c.against = j.at("against").get<std::string>();
  c.verdict = verdictFromName(j.at("verdict").get<std::string>());
  c.maxError = numberOr(j.at("max_error"), kInf);
  c.meanError = numberOr(j.at("mean_error"), kInf);
  c.rmsError = numberOr(j.at("rms_error"), kInf);
  c.psnr = numberOr(j.at("psnr"), kInf);
  c.maxX = count<int>(j.at("max_x"));
  c.maxY = count<int>(j.at("max_y"));
  c.compared = count<std::size_t>(j.at("compared"));
  c.failed = count<std::size_t>(j.at("failed"));
  c.warned = count<std::size_t>(j.at("warned"));
  const nlohmann::json& masked = j.at("masked");
  if (!masked.is_object())
    throw nlohmann::json::type_error::create(302, "masked must be an object", &masked);
  for (const auto& [reason, n] : masked.items()) c.masked[reason] = count<std::size_t>(n);
  c.problem = j.at("problem").get<std::string>();
  return c;
}

}  // namespace

nlohmann::json toJson(const CaseResult& r) {
  nlohmann::json varyings = nlohmann::json::array();
  for (const VaryingCheck& v : r.varyings) {
    nlohmann::json failures = nlohmann::json::array();
    for (const ComponentFailure& f : v.worstFailures)
      failures.push_back({{"vertex", f.vertex}, {"component", f.component},
                          {"observed", number(f.observed)}, {"reference", f.reference},
                          {"lo", f.lo}, {"hi", f.hi}, {"slack", number(f.slack)}});
    varyings.push_back({{"name", v.name},
                        {"checked", v.checked},
                        {"undefined", v.undefined},
                        {"failed", v.failed},
                        {"worst_slack", number(v.worstSlack)},
                        {"worst_vertex", v.worstVertex},
                        {"slack_histogram", v.slackHistogram},
                        {"first_failures", failures}});
  }
  nlohmann::json images = nlohmann::json::array();
  for (const ImageComparison& c : r.images) images.push_back(imageToJson(c));
  nlohmann::json reruns = nlohmann::json::array();
  for (Status s : r.reruns) reruns.push_back(statusName(s));
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
          {"images", images},
          {"compile_log", r.compileLog},
          {"seconds", r.seconds},
          {"backend_seconds", r.backendSeconds},
          {"oracle_seconds", r.oracleSeconds},
          {"reruns", reruns}};
}

CaseResult caseResultFromJson(const nlohmann::json& j) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
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
  r.vertices = count<std::size_t>(j.at("vertices"));
  for (const nlohmann::json& v : j.at("varyings")) {
    VaryingCheck check;
    check.name = v.at("name").get<std::string>();
    check.checked = count<std::size_t>(v.at("checked"));
    check.undefined = count<std::size_t>(v.at("undefined"));
    check.failed = count<std::size_t>(v.at("failed"));
    check.worstSlack = numberOr(v.at("worst_slack"), kInf);
    check.worstVertex = count<std::size_t>(v.at("worst_vertex"));
    if (v.contains("slack_histogram")) {  // absent from older records
      const nlohmann::json& bins = v.at("slack_histogram");
      if (!bins.is_array() || bins.size() != check.slackHistogram.size())
        throw nlohmann::json::type_error::create(
            302, "slack_histogram must hold " + std::to_string(check.slackHistogram.size()) + " counts", &bins);
      for (std::size_t k = 0; k < bins.size(); ++k) check.slackHistogram[k] = count<std::size_t>(bins[k]);
    }
    for (const nlohmann::json& f : v.at("first_failures"))
      check.worstFailures.push_back(
          {count<std::size_t>(f.at("vertex")), count<int>(f.at("component")),
           static_cast<float>(numberOr(f.at("observed"), std::nan(""))), f.at("reference").get<double>(),
           f.at("lo").get<double>(), f.at("hi").get<double>(), numberOr(f.at("slack"), kInf)});
    r.varyings.push_back(std::move(check));
  }
  for (const nlohmann::json& image : j.at("images")) r.images.push_back(imageFromJson(image));
  r.compileLog = j.at("compile_log").get<std::string>();
  r.seconds = j.at("seconds").get<double>();
  r.backendSeconds = j.at("backend_seconds").get<double>();
  r.oracleSeconds = j.at("oracle_seconds").get<double>();
  // Absent from records written before reruns existed.
  if (j.contains("reruns"))
    for (const nlohmann::json& s : j.at("reruns")) r.reruns.push_back(statusOf(s.get<std::string>()));
  return r;
}

}  // namespace snell
