#include "runner/checks/image_check_kind.h"

#include <fmt/format.h>

#include <chrono>
#include <limits>

#include "core/errors.h"
#include "oracle/vertex_oracle.h"
#include "runner/case_runner.h"
#include "runner/image_check.h"
#include "runner/json_fields.h"
#include "runner/listing_oracles.h"
#include "runner/run_helpers.h"

namespace snell {
namespace {

nlohmann::json comparisonToJson(const ImageComparison& c) {
  return {{"against", c.against},
          {"verdict", imageVerdictName(c.verdict)},
          {"max_error", jsonNumber(c.maxError)},
          {"mean_error", jsonNumber(c.meanError)},
          {"rms_error", jsonNumber(c.rmsError)},
          {"psnr", jsonNumber(c.psnr)},
          {"max_x", c.maxX},
          {"max_y", c.maxY},
          {"compared", c.compared},
          {"failed", c.failed},
          {"warned", c.warned},
          {"masked", c.masked},
          {"problem", c.problem}};
}

ImageVerdict verdictFromName(const std::string& name) {
  for (ImageVerdict v : {ImageVerdict::Pass, ImageVerdict::Warn, ImageVerdict::Fail})
    if (name == imageVerdictName(v)) return v;
  throw nlohmann::json::other_error::create(501, "unknown image verdict " + name, nullptr);
}

ImageComparison comparisonFromJson(const nlohmann::json& j) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  ImageComparison c;
  c.against = j.at("against").get<std::string>();
  c.verdict = verdictFromName(j.at("verdict").get<std::string>());
  c.maxError = jsonNumberOr(j.at("max_error"), kInf);
  c.meanError = jsonNumberOr(j.at("mean_error"), kInf);
  c.rmsError = jsonNumberOr(j.at("rms_error"), kInf);
  c.psnr = jsonNumberOr(j.at("psnr"), kInf);
  c.maxX = jsonCount<int>(j.at("max_x"));
  c.maxY = jsonCount<int>(j.at("max_y"));
  c.compared = jsonCount<std::size_t>(j.at("compared"));
  c.failed = jsonCount<std::size_t>(j.at("failed"));
  c.warned = jsonCount<std::size_t>(j.at("warned"));
  const nlohmann::json& masked = j.at("masked");
  if (!masked.is_object())
    throw nlohmann::json::type_error::create(302, "masked must be an object", &masked);
  for (const auto& [reason, n] : masked.items()) c.masked[reason] = jsonCount<std::size_t>(n);
  c.problem = j.at("problem").get<std::string>();
  return c;
}

// The largest error of the worst comparison that did not pass (against the
// golden, say, on a row that fails by it), else the largest against the CPU
// reference; "-" for a case that draws nothing.
std::string imageErrorCell(const CaseResult& r) {
  // The worst verdict first (a failure over a warning with a larger error),
  // then the largest error.
  const auto rank = [](ImageVerdict v) {
    return v == ImageVerdict::Fail ? 2 : v == ImageVerdict::Pass ? 0 : 1;
  };
  const ImageComparison* shown = nullptr;
  for (const ImageComparison& c : r.images)
    if (c.verdict != ImageVerdict::Pass &&
        (!shown || rank(c.verdict) > rank(shown->verdict) ||
         (rank(c.verdict) == rank(shown->verdict) && c.maxError > shown->maxError)))
      shown = &c;
  if (!shown)
    for (const ImageComparison& c : r.images)
      if (c.against == "reference") shown = &c;
  return shown ? fmt::format("{:.2e}", shown->maxError) : "-";
}

}  // namespace

void ImageCheckKind::validate(const Case& c, const ProgramSource&, const Scene& scene) const {
  const Manifest& m = *c.manifest;
  if (!scene.draws())
    manifestErrorAt(
        m, c.spec.line,
        fmt::format("scene `{}` draws nothing; its cases check [\"vectors\"] only", scene.name));
  drawingOracles(m);  // throws, naming the place, when there is no reference to draw
}

void ImageCheckKind::run(const Case& c, const ResolvedBindings& bindings, CheckEnvironment& env,
                         CaseResult& result) const {
  const Scene& scene = env.scenes.get(c.spec.scene);
  const ReferenceImage& reference = env.references.get(c, scene, bindings);
  const auto backendStart = std::chrono::steady_clock::now();
  const ImageCheck check = checkImage(env.backend, c, scene, bindings, reference, env.imageOptions,
                                      env.references.writesImages());
  result.backendSeconds += secondsSince(backendStart);
  if (!check.compiled) {
    result.status = Status::CompileError;
    result.compileLog = check.compileLog;
    result.message = check.compileLog;
    return;
  }
  for (const ImageComparison& comparison : check.comparisons) {
    result.images.push_back(comparison);
    if (comparison.verdict == ImageVerdict::Pass) continue;
    // Off the reference is wrong; off the golden is a change: a failure
    // beyond `fail`, a quality warning between `warn` and `fail`.
    const bool golden = comparison.against == "golden";
    result.status = worstOf(result.status, comparison.verdict == ImageVerdict::Fail ? Status::Fail
                                           : golden ? Status::QualityWarning
                                                    : Status::Pass);
    // Where to look: the heat map (none when the sizes differ).
    const std::string heatMap =
        comparison.problem.empty()
            ? fmt::format("; heat map {}", heatMapPath(env.imageOptions.outDir, c.id,
                                                       env.backend.name(), comparison.against)
                                               .string())
            : "";
    result.message +=
        fmt::format("image vs {}: {}{}; max error {:.6g} at ({}, {}), {} of {} pixels over {}{}\n",
                    comparison.against, imageVerdictName(comparison.verdict),
                    comparison.problem.empty() ? "" : " (" + comparison.problem + ")",
                    comparison.maxError, comparison.maxX, comparison.maxY, comparison.failed,
                    comparison.compared, c.spec.image.fail, heatMap);
  }
  if (!check.goldenAdvice.empty()) result.message += check.goldenAdvice + "\n";
  if (!check.goldenNote.empty()) result.message += check.goldenNote + "\n";
  if (!check.goldenProblem.empty()) {
    result.status = worstOf(result.status, Status::Fail);
    result.message += check.goldenProblem + "\n";
  }
}

void ImageCheckKind::writeJson(const CaseResult& r, nlohmann::json& record) const {
  nlohmann::json images = nlohmann::json::array();
  for (const ImageComparison& c : r.images) images.push_back(comparisonToJson(c));
  record["images"] = images;
}

void ImageCheckKind::readJson(const nlohmann::json& record, CaseResult& r) const {
  for (const nlohmann::json& image : record.at("images"))
    r.images.push_back(comparisonFromJson(image));
}

std::vector<SummaryColumn> ImageCheckKind::summaryColumns() const {
  return {{"image err", 10, imageErrorCell}};
}

std::string ImageCheckKind::junitMessage(const CaseResult& r) const {
  std::string message;
  for (const ImageComparison& c : r.images) {
    if (c.verdict == ImageVerdict::Pass) continue;
    message += fmt::format("{}image vs {}: {}, max error {:.3g}, {} of {} pixels over the limit",
                           message.empty() ? "" : "; ", c.against, imageVerdictName(c.verdict),
                           c.maxError, c.failed, c.compared);
  }
  return message;
}

}  // namespace snell
