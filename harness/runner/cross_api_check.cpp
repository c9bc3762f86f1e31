#include "runner/cross_api_check.h"

#include <fmt/format.h>

#include <map>
#include <vector>

#include "compare/image_io.h"
#include "core/errors.h"
#include "runner/image_check.h"
#include "runner/oracle_store/image_results.h"

namespace snell {

void checkAcrossApis(const std::vector<Case>& cases, const std::filesystem::path& outDir,
                     std::vector<CaseResult>& results, const OracleStore* store) {
  std::map<std::string, std::map<std::string, CaseResult*>> byCase;
  for (CaseResult& r : results) byCase[r.caseId][r.backend] = &r;
  const auto renderedAndWithinSpec = [](const CaseResult& r) {
    return r.status == Status::Pass || r.status == Status::QualityWarning;
  };
  for (const Case& c : cases) {
    if (!c.spec.has("image")) continue;
    // Chosen before any pair is compared: a warning from one pair must not
    // keep a backend out of the next.
    std::vector<CaseResult*> ran;  // by backend name, so pairs come in a fixed order
    for (const auto& [backend, result] : byCase[c.id])
      if (renderedAndWithinSpec(*result)) ran.push_back(result);
    for (std::size_t i = 0; i < ran.size(); ++i) {
      for (std::size_t j = i + 1; j < ran.size(); ++j) {
        CaseResult& a = *ran[i];
        CaseResult& b = *ran[j];
        ImageComparison comparison;
        const std::string against = std::string(kOtherBackendPrefix) + a.backend + "/" + b.backend;
        try {
          comparison = compareImagesKept(
              store, against, readImageKept(store, renderedImagePath(outDir, c.id, b.backend)),
              readImageKept(store, renderedImagePath(outDir, c.id, a.backend)),
              maskFromImage(readImageKept(store, maskImagePath(outDir, c.id))), c.spec.image);
        } catch (const UsageError& error) {
          comparison.against = against;
          comparison.verdict = ImageVerdict::Fail;
          comparison.problem = error.what();
        }
        for (CaseResult* r : {&a, &b}) {
          r->images.push_back(comparison);
          if (comparison.verdict == ImageVerdict::Pass) continue;
          r->status = worstOf(r->status, Status::CompatibilityWarning);
          if (!comparison.problem.empty()) {
            r->message += fmt::format("{} and {} could not be compared: {}\n", a.backend, b.backend,
                                      comparison.problem);
            continue;
          }
          r->message += fmt::format(
              "{} and {} differ: max error {:.6g} at ({}, {}), {} of {} pixels over {}\n",
              a.backend, b.backend, comparison.maxError, comparison.maxX, comparison.maxY,
              comparison.failed, comparison.compared, c.spec.image.fail);
        }
      }
    }
  }
}

}  // namespace snell
