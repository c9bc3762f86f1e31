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

// Adds an "other-backend:A/B" comparison to both results of every pair of
// backends that rendered an image case into `outDir`. With a store, the
// images read and the comparisons are kept there (runner/oracle_store).
void checkAcrossApis(const std::vector<Case>& cases, const std::filesystem::path& outDir,
                     std::vector<CaseResult>& results, const OracleStore* store = nullptr);

}  // namespace snell
