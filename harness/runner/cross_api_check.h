#pragma once
// OpenGL against Vulkan, once both have rendered a case: is the listing
// portable? Two images that are each within spec of the reference but
// differ from each other beyond the warn threshold make both results
// CompatibilityWarning.
#include <filesystem>
#include <vector>

#include "core/case.h"
#include "runner/case_result.h"

namespace snell {

// Adds an "other-api" comparison to every pair of gl/vk results of an image
// case whose images were both written to `outDir`.
void checkAcrossApis(const std::vector<Case>& cases, const std::filesystem::path& outDir,
                     std::vector<CaseResult>& results);

}  // namespace snell
