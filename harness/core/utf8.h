#pragma once
// UTF-8 as written files need it: TOML, JSON and XML readers refuse a byte
// that is not part of a well-formed character, and text from outside (a
// shader's comment in Latin-1, a driver's log) may hold one.
#include <fmt/format.h>

#include <algorithm>
#include <cstddef>
#include <string>
#include <string_view>

namespace snell {

struct Utf8Character {
  std::size_t length = 0;  // 0: the byte at `at` starts no well-formed character
  char32_t code = 0;
};

// The character at `text[at]`: shortest form, no surrogate, at most U+10FFFF.
inline Utf8Character utf8CharacterAt(std::string_view text, std::size_t at) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[at + k]); };
  const unsigned char lead = byte(0);
  std::size_t length = 0;
  char32_t code = 0;
  if (lead < 0x80) return {1, lead};
  if (lead >= 0xC2 && lead <= 0xDF)
    length = 2, code = lead & 0x1F;
  else if (lead >= 0xE0 && lead <= 0xEF)
    length = 3, code = lead & 0x0F;
  else if (lead >= 0xF0 && lead <= 0xF4)
    length = 4, code = lead & 0x07;
  else
    return {};
  if (at + length > text.size()) return {};
  for (std::size_t k = 1; k < length; ++k) {
    if ((byte(k) & 0xC0) != 0x80) return {};
    code = (code << 6) | (byte(k) & 0x3F);
  }
  const bool shortest = (length == 2 && code >= 0x80) || (length == 3 && code >= 0x800) ||
                        (length == 4 && code >= 0x10000 && code <= 0x10FFFF);
  const bool surrogate = code >= 0xD800 && code <= 0xDFFF;
  if (!shortest || surrogate) return {};
  return {length, code};
}

inline bool isUtf8(std::string_view text) {
  for (std::size_t at = 0; at < text.size();) {
    const std::size_t length = utf8CharacterAt(text, at).length;
    if (length == 0) return false;
    at += length;
  }
  return true;
}

// `text` with each byte that starts no character, and each byte of a
// character `writable(code)` refuses (a control character the output's
// format forbids), spelled out as \xNN.
template <class Writable>
std::string utf8SpellingOut(std::string_view text, Writable writable) {
  std::string safe;
  safe.reserve(text.size());
  for (std::size_t at = 0; at < text.size();) {
    const Utf8Character c = utf8CharacterAt(text, at);
    if (c.length == 0 || !writable(c.code)) {
      for (std::size_t k = 0; k < std::max<std::size_t>(c.length, 1); ++k)
        safe += fmt::format("\\x{:02x}", static_cast<unsigned char>(text[at + k]));
      at += std::max<std::size_t>(c.length, 1);
    } else {
      safe.append(text.substr(at, c.length));
      at += c.length;
    }
  }
  return safe;
}

// `text` with each byte that starts no character spelled out as \xNN.
inline std::string utf8SpellingOutOthers(std::string_view text) {
  return utf8SpellingOut(text, [](char32_t) { return true; });
}

}  // namespace snell
