#pragma once
// Messages to a person, on stderr or a log stream. A write that fails
// (stderr closed, /dev/full, a reader that has left) loses the message and
// nothing else: fmt::print throws on it, and from a catch block or a
// server's log that ended the process with abort() instead of its exit code.
#include <fmt/format.h>

#include <cstdio>
#include <string>
#include <utility>

namespace snell {

inline void writeMessage(std::FILE* stream, const std::string& text) noexcept {
  std::fwrite(text.data(), 1, text.size(), stream);
  std::fflush(stream);
  std::clearerr(stream);
}

template <class... Args>
void printMessage(std::FILE* stream, fmt::format_string<Args...> format, Args&&... args) {
  writeMessage(stream, fmt::format(format, std::forward<Args>(args)...));
}

}  // namespace snell
