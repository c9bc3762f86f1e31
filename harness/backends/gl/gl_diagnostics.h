#pragma once
// Mesa's GLSL compiler writes "0:LINE(COLUMN): error: MESSAGE" (or
// "warning:"): the placed messages of one stage's log.
#include <string>
#include <vector>

#include "backends/backend.h"

namespace snell::gl {

std::vector<CompileDiagnostic> parseMesaLog(const std::string& stage, const std::string& log);

}  // namespace snell::gl
