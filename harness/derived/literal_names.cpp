#include "derived/literal_names.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <regex>

namespace snell::derived {
namespace {

bool isEs(const std::string& text) {
  static const std::regex kVersion(R"(^[ \t]*#[ \t]*version[ \t]+([0-9]+)([ \t]+es)?)",
                                   std::regex::multiline);
  std::smatch match;
  if (!std::regex_search(text, match, kVersion)) return false;
  return match[2].matched || match[1].str() == "100";
}

bool identifierStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool identifierByte(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
bool digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }

// The end of the preprocessing number starting at `at` (digits, letters,
// '.', '_', and a sign after an exponent's e).
std::size_t numberEnd(const std::string& text, std::size_t at) {
  const bool hex = text.compare(at, 2, "0x") == 0 || text.compare(at, 2, "0X") == 0;
  std::size_t end = at;
  while (end < text.size()) {
    const char c = text[end];
    const bool sign = (c == '+' || c == '-') && !hex && end > at &&
                      (text[end - 1] == 'e' || text[end - 1] == 'E');
    if (!identifierByte(c) && c != '.' && !sign) break;
    ++end;
  }
  return end;
}

// A single-precision float literal's value; none for ints, doubles (`lf`)
// and anything strtod does not read whole.
bool floatLiteral(const std::string& token, double& value) {
  if (token.size() > 1 && (token[1] == 'x' || token[1] == 'X')) return false;
  if (token.find_first_of(".eE") == std::string::npos) return false;
  std::string core = token;
  if (core.size() > 2 && (core.ends_with("lf") || core.ends_with("LF"))) return false;
  if (core.back() == 'f' || core.back() == 'F') core.pop_back();
  char* end = nullptr;
  value = std::strtod(core.c_str(), &end);
  return end == core.c_str() + core.size();
}

enum class Directive { None, Define, Other };

}  // namespace

NamedLiterals withLiteralsNamed(const std::string& text) {
  NamedLiterals named;
  const bool es = isEs(text);
  std::string prefix = "snell_literal_";
  while (text.find(prefix) != std::string::npos) prefix.insert(0, "x");
  std::string& out = named.text;
  out.reserve(text.size() + text.size() / 2);
  std::size_t declarationsAt = std::string::npos;
  int depth = 0;
  bool lineStart = true;
  Directive directive = Directive::None;
  std::size_t i = 0;
  // #if / #ifdef / #ifndef blocks open around the text: the declarations
  // go before the first token outside all of them, never into a branch the
  // preprocessor may drop.
  int conditionals = 0;
  const auto firstToken = [&] {
    if (declarationsAt == std::string::npos && directive == Directive::None && conditionals == 0)
      declarationsAt = out.size();
  };
  while (i < text.size()) {
    const char c = text[i];
    if (c == '/' && text.compare(i, 2, "//") == 0) {
      const std::size_t end = std::min(text.find('\n', i), text.size());
      out.append(text, i, end - i);
      i = end;
      continue;
    }
    if (c == '/' && text.compare(i, 2, "/*") == 0) {
      const std::size_t close = text.find("*/", i + 2);
      const std::size_t end = close == std::string::npos ? text.size() : close + 2;
      out.append(text, i, end - i);
      i = end;
      continue;
    }
    if (c == '\n') {
      // A directive goes on past a line that ends in a backslash.
      std::size_t last = out.size();
      while (last > 0 && (out[last - 1] == '\r' || out[last - 1] == ' ' || out[last - 1] == '\t'))
        --last;
      if (!(last > 0 && out[last - 1] == '\\')) directive = Directive::None;
      lineStart = true;
      out += c;
      ++i;
      continue;
    }
    if (std::isspace(static_cast<unsigned char>(c))) {
      out += c;
      ++i;
      continue;
    }
    if (c == '#' && lineStart) {
      std::size_t at = i + 1;
      while (at < text.size() && (text[at] == ' ' || text[at] == '\t')) ++at;
      std::size_t nameEnd = at;
      while (nameEnd < text.size() && identifierByte(text[nameEnd])) ++nameEnd;
      const std::string name = text.substr(at, nameEnd - at);
      directive = name == "define" ? Directive::Define : Directive::Other;
      if (name == "if" || name == "ifdef" || name == "ifndef") ++conditionals;
      if (name == "endif" && conditionals > 0) --conditionals;
      out.append(text, i, nameEnd - i);
      i = nameEnd;
      lineStart = false;
      continue;
    }
    lineStart = false;
    if (directive == Directive::Other) {
      out += c;
      ++i;
      continue;
    }
    if (identifierStart(c)) {
      firstToken();
      std::size_t end = i;
      while (end < text.size() && identifierByte(text[end])) ++end;
      out.append(text, i, end - i);
      i = end;
      continue;
    }
    if (digit(c) || (c == '.' && i + 1 < text.size() && digit(text[i + 1]))) {
      firstToken();
      const std::size_t end = numberEnd(text, i);
      const std::string token = text.substr(i, end - i);
      double value = 0.0;
      const bool global = depth == 0 || directive == Directive::Define;
      if (!(es && global) && floatLiteral(token, value)) {
        const std::string name = prefix + std::to_string(named.values.size());
        named.values.emplace(name, value);
        out += name;
      } else {
        out += token;
      }
      i = end;
      continue;
    }
    firstToken();
    if (directive == Directive::None) {
      if (c == '{') ++depth;
      if (c == '}') --depth;
    }
    out += c;
    ++i;
  }
  if (!named.values.empty() && declarationsAt != std::string::npos) {
    std::string declarations = es ? "uniform highp float " : "uniform float ";
    bool first = true;
    for (const auto& [name, value] : named.values) {
      declarations += (first ? "" : ", ") + name;
      first = false;
    }
    out.insert(declarationsAt, declarations + "; ");
  }
  return named;
}

}  // namespace snell::derived
