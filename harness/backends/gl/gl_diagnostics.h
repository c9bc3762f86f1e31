#pragma once
// The placed messages of one stage's GL info log. Each GL driver writes its
// own shape; those read here, as seen from the drivers themselves:
//   Mesa:   "0:LINE(COLUMN): error: MESSAGE" (or "warning:")
//   NVIDIA: "0(LINE) : error C0000: MESSAGE" (or "warning C7011:"), seen
//           from NVIDIA 580.159.04 on an H200
// A line of another shape is left out: it places nothing.
#include <string>
#include <vector>

#include "backends/backend.h"

namespace snell::gl {

std::vector<CompileDiagnostic> parseInfoLog(const std::string& stage, const std::string& log);

}  // namespace snell::gl
