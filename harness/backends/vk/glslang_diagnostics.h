#pragma once
// glslang writes "ERROR: FILE:LINE: MESSAGE" (or "WARNING:"): the placed
// messages of one stage's info log.
#include <string>
#include <vector>

#include "backends/backend.h"

namespace snell::vk {

std::vector<CompileDiagnostic> parseGlslangLog(const std::string& stage, const std::string& log);

}  // namespace snell::vk
