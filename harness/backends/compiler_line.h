#pragma once
// Line numbers read from a compiler's log (gl_diagnostics, glslang_diagnostics).
#include <charconv>
#include <string_view>
#include <system_error>

namespace snell {

// A line number as a compiler's log prints it. One past int's range (the
// shader's own `#line 99999999999`) names no line: 0, where std::stoi threw.
inline int compilerLineNumber(std::string_view digits) {
  int line = 0;
  const auto parsed = std::from_chars(digits.data(), digits.data() + digits.size(), line);
  return parsed.ec == std::errc() ? line : 0;
}

}  // namespace snell
