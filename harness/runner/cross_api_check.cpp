#include "runner/cross_api_check.h"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include "compare/image_io.h"
#include "core/errors.h"
#include "runner/image_check.h"
#include "runner/oracle_store/image_results.h"

namespace snell {

namespace {

std::string pairName(const CaseResult& a, const CaseResult& b) {
  return std::string(kOtherBackendPrefix) + a.backend + "/" + b.backend;
}

bool recorded(const CaseResult& r, const std::string& against) {
  return std::any_of(r.images.begin(), r.images.end(),
                     [&](const ImageComparison& c) { return c.against == against; });
}

}  // namespace

std::vector<BackendPair> pendingBackendPairs(const std::vector<Case>& cases,
                                             std::vector<CaseResult>& results) {
  std::map<std::string, std::map<std::string, CaseResult*>> byCase;
  for (CaseResult& r : results) byCase[r.caseId][r.backend] = &r;
  const auto renderedAndWithinSpec = [](const CaseResult& r) {
    return r.status == Status::Pass || r.status == Status::QualityWarning;
  };
  std::vector<BackendPair> pairs;
  for (const Case& c : cases) {
    if (!c.spec.has("image")) continue;
    // Chosen before any pair is compared: a warning from one pair must not
    // keep a backend out of the next.
    std::vector<CaseResult*> ran;  // by backend name, so pairs come in a fixed order
    for (const auto& [backend, result] : byCase[c.id])
      if (renderedAndWithinSpec(*result)) ran.push_back(result);
    for (std::size_t i = 0; i < ran.size(); ++i)
      for (std::size_t j = i + 1; j < ran.size(); ++j)
        if (const std::string name = pairName(*ran[i], *ran[j]);
            !recorded(*ran[i], name) && !recorded(*ran[j], name))
          pairs.push_back({&c, ran[i], ran[j]});
  }
  return pairs;
}

void checkAcrossApis(const std::vector<Case>& cases, const std::filesystem::path& outDir,
                     std::vector<CaseResult>& results, const OracleStore* store) {
  for (const BackendPair& pair : pendingBackendPairs(cases, results)) {
    const Case& c = *pair.imageCase;
    CaseResult& a = *pair.a;
    CaseResult& b = *pair.b;
    ImageComparison comparison;
    const std::string against = pairName(a, b);
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
      r->message +=
          fmt::format("{} and {} differ: max error {:.6g} at ({}, {}), {} of {} pixels over {}\n",
                      a.backend, b.backend, comparison.maxError, comparison.maxX, comparison.maxY,
                      comparison.failed, comparison.compared, c.spec.image.fail);
    }
  }
}

}  // namespace snell
