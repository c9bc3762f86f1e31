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

// A value given empty (an unset shell variable) would otherwise stand for
// the option's default: another path, every case, the default device,
// every backend. `what` names the value, `hint` how to give one.
inline CLI::Validator nonEmpty(const std::string& what, const std::string& hint = "give one") {
  return CLI::Validator(
      [what, hint](const std::string& text) -> std::string {
        return text.empty() ? "an empty " + what + "; " + hint + ", or leave the option out" : "";
      },
      "");
}

inline CLI::Validator nonEmptyPath() { return nonEmpty("path"); }
inline CLI::Validator nonEmptyGlob() {
  return nonEmpty("glob", "give one ('*' matches every case)");
}

// A floating-point value: CLI11 takes an empty one as 0 and says only
// "Could not convert" of one that is not a number. `what` says what to give.
inline CLI::Validator number(const std::string& what) {
  return CLI::Validator(
      [what](const std::string& text) -> std::string {
        if (text.empty()) return "empty; give " + what;
        char* end = nullptr;
        std::strtod(text.c_str(), &end);
        return *end == '\0' ? "" : "`" + text + "` is not a number; give " + what;
      },
      "");
}

// A count of whole units (seconds, repeats): CLI11 turns "1.5" for an
// unsigned option into "Value 1.5 not in range", which hides the reason.
inline CLI::Validator wholeNumber() {
  return CLI::Validator(
      [](const std::string& text) -> std::string {
        const bool digits =
            !text.empty() && text.find_first_not_of("0123456789") == std::string::npos;
        return digits ? "" : "give a whole number";
      },
      "");
}

}  // namespace snell::cli
