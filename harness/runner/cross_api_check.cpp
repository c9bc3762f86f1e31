#include "runner/cross_api_check.h"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <string>
#include <utility>
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

const ImageComparison* recorded(const CaseResult& r, const std::string& against) {
  const auto it = std::find_if(r.images.begin(), r.images.end(),
                               [&](const ImageComparison& c) { return c.against == against; });
  return it == r.images.end() ? nullptr : &*it;
}

// Adds the comparison of `a` and `b` to `r`, one of the two, with what it
// does to r's status and message.
void addComparison(CaseResult& r, const ImageComparison& comparison, const CaseResult& a,
                   const CaseResult& b, const Case& c) {
  r.images.push_back(comparison);
  if (comparison.verdict == ImageVerdict::Pass) return;
  r.status = worstOf(r.status, Status::CompatibilityWarning);
  if (!comparison.problem.empty()) {
    r.message += fmt::format("{} and {} could not be compared: {}\n", a.backend, b.backend,
                             comparison.problem);
    return;
  }
  r.message +=
      fmt::format("{} and {} differ: max error {:.6g} at ({}, {}), {} of {} pixels over {}\n",
                  a.backend, b.backend, comparison.maxError, comparison.maxX, comparison.maxY,
                  comparison.failed, comparison.compared, c.spec.image.fail);
}

// The results of each image case whose images are within the spec, by
// backend name (pairs then come in a fixed order).
std::vector<std::pair<const Case*, std::vector<CaseResult*>>> withinSpecByCase(
    const std::vector<Case>& cases, std::vector<CaseResult>& results) {
  std::map<std::string, std::map<std::string, CaseResult*>> byCase;
  for (CaseResult& r : results) byCase[r.caseId][r.backend] = &r;
  std::vector<std::pair<const Case*, std::vector<CaseResult*>>> out;
  for (const Case& c : cases) {
    if (!c.spec.has("image")) continue;
    std::vector<CaseResult*> ran;
    for (const auto& [backend, result] : byCase[c.id])
      if (renderedWithinSpec(result->status)) ran.push_back(result);
    out.push_back({&c, std::move(ran)});
  }
  return out;
}

}  // namespace

bool renderedWithinSpec(Status status) {
  // CompatibilityWarning is set by this check alone: a result that has it
  // was within the spec and warned against another backend, and is still
  // held against the backends it has not met (shards merged, a run resumed).
  return status == Status::Pass || status == Status::QualityWarning ||
         status == Status::CompatibilityWarning;
}

std::vector<BackendPair> pendingBackendPairs(const std::vector<Case>& cases,
                                             std::vector<CaseResult>& results) {
  std::vector<BackendPair> pairs;
  // Chosen before any pair is compared: a warning from one pair must not
  // keep a backend out of the next.
  for (const auto& [c, ran] : withinSpecByCase(cases, results))
    for (std::size_t i = 0; i < ran.size(); ++i)
      for (std::size_t j = i + 1; j < ran.size(); ++j)
        if (const std::string name = pairName(*ran[i], *ran[j]);
            !recorded(*ran[i], name) && !recorded(*ran[j], name))
          pairs.push_back({c, ran[i], ran[j]});
  return pairs;
}

void checkAcrossApis(const std::vector<Case>& cases, const std::filesystem::path& outDir,
                     std::vector<CaseResult>& results, const OracleStore* store) {
  // A pair recorded on one side only (a result re-run beside its partner's
  // kept one) gets the same comparison on the other: no image is read.
  for (const auto& [c, ran] : withinSpecByCase(cases, results))
    for (std::size_t i = 0; i < ran.size(); ++i)
      for (std::size_t j = i + 1; j < ran.size(); ++j) {
        const std::string name = pairName(*ran[i], *ran[j]);
        const ImageComparison* onA = recorded(*ran[i], name);
        const ImageComparison* onB = recorded(*ran[j], name);
        if (onA && !onB) addComparison(*ran[j], ImageComparison(*onA), *ran[i], *ran[j], *c);
        if (onB && !onA) addComparison(*ran[i], ImageComparison(*onB), *ran[i], *ran[j], *c);
      }
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
    addComparison(a, comparison, a, b, c);
    addComparison(b, comparison, a, b, c);
  }
}

}  // namespace snell
