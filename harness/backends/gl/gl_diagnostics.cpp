#include "backends/gl/gl_diagnostics.h"

#include <regex>
#include <sstream>

namespace snell::gl {

std::vector<CompileDiagnostic> parseMesaLog(const std::string& stage, const std::string& log) {
  static const std::regex kPlaced(R"(^\s*\d+:(\d+)\(\d+\):\s*(error|warning):\s*(.*)$)");
  std::vector<CompileDiagnostic> out;
  std::istringstream lines(log);
  for (std::string line; std::getline(lines, line);) {
    std::smatch match;
    if (!std::regex_match(line, match, kPlaced)) continue;
    out.push_back({stage, std::stoi(match[1]), match[2] == "error", match[3]});
  }
  return out;
}

}  // namespace snell::gl
