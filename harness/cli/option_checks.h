#pragma once
// Checks of option values beyond CLI11's own.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

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

// A list of whole numbers joined by commas (`--resolutions 128,256,512`),
// checked as given: CLI11's own delimiter drops an empty item ("16,,32"),
// more likely a number left out than meant, and says only "Could not
// convert" of an item that is not a number. `what` names the list, `hint`
// says how to give one. Ranges are the command's to check.
inline CLI::Option* addWholeNumberList(CLI::App& app, const std::string& name,
                                       std::vector<int>& target, const std::string& description,
                                       const std::string& what, const std::string& hint) {
  const auto items = [](const std::string& text) {
    std::vector<std::string> parts;
    std::size_t start = 0;
    for (;;) {
      const std::size_t comma = text.find(',', start);
      parts.push_back(text.substr(start, comma == std::string::npos ? comma : comma - start));
      if (comma == std::string::npos) return parts;
      start = comma + 1;
    }
  };
  // Each value given (the option repeated, or its values apart) is a list;
  // the lists join, as CLI11's own vectors do.
  CLI::Option* option = app.add_option(
      name,
      [&target, items](const CLI::results_t& lists) {
        target.clear();
        for (const std::string& text : lists)
          for (const std::string& item : items(text)) target.push_back(std::stoi(item));
        return true;
      },
      description);
  option->expected(1, CLI::detail::expected_max_vector_size);
  option->allow_extra_args();
  option->check(CLI::Validator(
      [what, hint, items](const std::string& text) -> std::string {
        if (text.empty()) return "an empty " + what + "; " + hint + ", or leave the option out";
        const std::vector<std::string> parts = items(text);
        for (std::size_t k = 0; k < parts.size(); ++k) {
          const std::string& item = parts[k];
          if (item.empty()) return fmt::format("item {} of `{}` is empty; {}", k + 1, text, hint);
          if (item.find_first_not_of("0123456789") != std::string::npos)
            return fmt::format("`{}` is not a whole number; {}", item, hint);
          // Nine digits stay inside int (leading zeros aside); the
          // command's range check says more.
          const std::size_t first = std::min(item.find_first_not_of('0'), item.size() - 1);
          if (item.size() - first > 9) return fmt::format("`{}` is too large; {}", item, hint);
        }
        return "";
      },
      ""));
  option->type_name("INT,...");
  if (!target.empty()) option->default_str(fmt::format("{}", fmt::join(target, ",")));
  return option;
}

}  // namespace snell::cli
