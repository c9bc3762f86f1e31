#pragma once
// The one validation step: everything a case needs is read and checked
// before any driver is loaded, so a broken manifest stops `run`, `bless`,
// `list` and the worker alike with exit 2 and FILE:LINE. What it accepts,
// no later step rejects for a reason it could have seen.
#include <string>
#include <vector>

#include "core/case.h"
#include "runner/case_runner.h"

namespace snell {

// Throws UsageError "FILE:LINE: what is wrong; what to do".
void validateCase(const Case& c, SceneCache& scenes);

// Every case, with the scenes of the `shaders` folder.
void validateCases(const std::vector<Case>& cases, const std::string& shaders);

}  // namespace snell
