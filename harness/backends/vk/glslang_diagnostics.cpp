#include "backends/vk/glslang_diagnostics.h"

#include <regex>
#include <sstream>

#include "backends/compiler_line.h"

namespace snell::vk {

std::vector<CompileDiagnostic> parseGlslangLog(const std::string& stage, const std::string& log) {
  // The file name may hold colons; the line is the last ":DIGITS:" before
  // the message.
  static const std::regex kPlaced(R"(^(ERROR|WARNING): (.*):(\d+): (.*)$)");
  std::vector<CompileDiagnostic> out;
  std::istringstream lines(log);
  for (std::string line; std::getline(lines, line);) {
    std::smatch match;
    if (!std::regex_match(line, match, kPlaced)) continue;
    out.push_back({stage, compilerLineNumber(match[3].str()), match[1] == "ERROR", match[4]});
  }
  return out;
}

}  // namespace snell::vk
