#pragma once
// Every pair of backends that rendered a case, once all have: is the
// listing portable (OpenGL against Vulkan), and do drivers of one API agree?
// Two images that are each within spec of the reference but differ from
// each other beyond the warn threshold make both results CompatibilityWarning.
#include <filesystem>
#include <vector>

#include "core/case.h"
#include "runner/case_result.h"
#include "runner/oracle_store/oracle_store.h"

namespace snell {

// Two backends' results of one image case whose images are to be compared.
struct BackendPair {
  const Case* imageCase;
  CaseResult* a;  // the backend whose name sorts first
  CaseResult* b;
};

// Whether a result's image is one to hold against other backends': Pass,
// QualityWarning or CompatibilityWarning (an image already off the
// reference is not compared again).
bool renderedWithinSpec(Status status);

// The pairs not compared yet: both results rendered within the spec and no
// "other-backend:A/B" recorded on them, as after a run resumed or shards
// merged, where some pairs were compared in a job of their own.
std::vector<BackendPair> pendingBackendPairs(const std::vector<Case>& cases,
                                             std::vector<CaseResult>& results);

// Adds an "other-backend:A/B" comparison to both results of every pending
// pair of backends that rendered an image case into `outDir`. With a store,
// the images read and the comparisons are kept there (runner/oracle_store).
void checkAcrossApis(const std::vector<Case>& cases, const std::filesystem::path& outDir,
                     std::vector<CaseResult>& results, const OracleStore* store = nullptr);

}  // namespace snell
