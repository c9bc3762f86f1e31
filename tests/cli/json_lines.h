#pragma once
// The JSON objects among a command's output lines (`snell eval` answers),
// skipping the plain-text messages printed beside them.
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

namespace snell::testing {

inline std::vector<nlohmann::json> jsonLines(const std::string& text) {
  std::vector<nlohmann::json> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    if (!line.empty() && line[0] == '{') lines.push_back(nlohmann::json::parse(line));
  return lines;
}

}  // namespace snell::testing
