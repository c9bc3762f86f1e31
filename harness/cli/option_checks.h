#pragma once
// Checks of option values beyond CLI11's own.
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdlib>
#include <string>

namespace snell::cli {

// CLI::Range lets nan through (every comparison with it is false): added
// after a Range on a floating-point option, this refuses it.
inline CLI::Validator notNan() {
  return CLI::Validator(
      [](const std::string& text) -> std::string {
        return std::isnan(std::strtod(text.c_str(), nullptr)) ? "a number is needed, not nan" : "";
      },
      "");
}

// A path given empty (an unset shell variable) would otherwise stand for
// the option's default, which is another path than the one meant.
inline CLI::Validator nonEmptyPath() {
  return CLI::Validator(
      [](const std::string& text) -> std::string {
        return text.empty() ? "an empty path; give one, or leave the option out" : "";
      },
      "");
}

}  // namespace snell::cli
