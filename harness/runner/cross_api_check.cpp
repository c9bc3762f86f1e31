#include "runner/cross_api_check.h"

#include <fmt/format.h>

#include <map>

#include "compare/image_io.h"
#include "core/errors.h"
#include "runner/image_check.h"

namespace snell {

void checkAcrossApis(const std::vector<Case>& cases, const std::filesystem::path& outDir,
                     std::vector<CaseResult>& results) {
  std::map<std::string, std::map<std::string, CaseResult*>> byCase;
  for (CaseResult& r : results) byCase[r.caseId][r.backend] = &r;
  for (const Case& c : cases) {
    if (!c.spec.has("image")) continue;
    auto& pair = byCase[c.id];
    if (!pair.count("gl") || !pair.count("vk")) continue;
    CaseResult& gl = *pair["gl"];
    CaseResult& vk = *pair["vk"];
    const auto renderedAndWithinSpec = [](const CaseResult& r) {
      return r.status == Status::Pass || r.status == Status::QualityWarning;
    };
    if (!renderedAndWithinSpec(gl) || !renderedAndWithinSpec(vk)) continue;
    ImageComparison comparison;
    try {
      comparison = compareImages("other-api", readImage(renderedImagePath(outDir, c.id, "vk")),
                                 readImage(renderedImagePath(outDir, c.id, "gl")),
                                 maskFromImage(readImage(maskImagePath(outDir, c.id))), c.spec.image);
    } catch (const UsageError& error) {
      comparison.against = "other-api";
      comparison.verdict = ImageVerdict::Fail;
      comparison.problem = error.what();
    }
    for (CaseResult* r : {&gl, &vk}) {
      r->images.push_back(comparison);
      if (comparison.verdict == ImageVerdict::Pass) continue;
      r->status = worstOf(r->status, Status::CompatibilityWarning);
      r->message += fmt::format("OpenGL and Vulkan differ: max error {:.6g} at ({}, {}), {} of {} "
                                "pixels over {}{}\n",
                                comparison.maxError, comparison.maxX, comparison.maxY,
                                comparison.failed, comparison.compared, c.spec.image.fail,
                                comparison.problem.empty() ? "" : " (" + comparison.problem + ")");
    }
  }
}

}  // namespace snell
