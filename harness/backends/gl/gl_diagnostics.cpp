#include "backends/gl/gl_diagnostics.h"

#include <regex>
#include <sstream>

#include "backends/compiler_line.h"

namespace snell::gl {

std::vector<CompileDiagnostic> parseInfoLog(const std::string& stage, const std::string& log) {
  static const std::regex kMesa(R"(^\s*\d+:(\d+)\(\d+\):\s*(error|warning):\s*(.*)$)");
  static const std::regex kNvidia(R"(^\s*\d+\((\d+)\)\s*:\s*(error|warning)\s+C\d+:\s*(.*)$)");
  std::vector<CompileDiagnostic> out;
  std::istringstream lines(log);
  for (std::string line; std::getline(lines, line);) {
    std::smatch match;
    if (std::regex_match(line, match, kMesa) || std::regex_match(line, match, kNvidia))
      out.push_back({stage, compilerLineNumber(match[1].str()), match[2] == "error", match[3]});
  }
  return out;
}

}  // namespace snell::gl
