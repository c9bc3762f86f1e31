#pragma once
// Checks of numeric options beyond CLI11's own.
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

}  // namespace snell::cli
