#include "core/glsl_statements.h"

#include <algorithm>
#include <cctype>
#include <string_view>

#include "core/glsl_declarations.h"

namespace snell {
namespace {

bool identifierChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

int lineAt(const std::string& text, std::size_t at) {
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
}

std::size_t skipSpace(const std::string& text, std::size_t at) {
  while (at < text.size() && std::isspace(static_cast<unsigned char>(text[at]))) ++at;
  return at;
}

// Whether `word` is at `at` as a whole identifier.
bool wordAt(const std::string& text, std::size_t at, std::string_view word) {
  return text.compare(at, word.size(), word) == 0 && (at == 0 || !identifierChar(text[at - 1])) &&
         (at + word.size() >= text.size() || !identifierChar(text[at + word.size()]));
}

}  // namespace

std::size_t mainBody(const std::string& text) {
  // `void main()` or `void main(void)`, then `{`: scanned by hand, as a
  // regular expression would recurse once per character of a long space run.
  for (std::size_t at = text.find("main"); at != std::string::npos;
       at = text.find("main", at + 1)) {
    if (!wordAt(text, at, "main")) continue;
    std::size_t before = at;
    while (before > 0 && std::isspace(static_cast<unsigned char>(text[before - 1]))) --before;
    if (before == at || before < 4 || !wordAt(text, before - 4, "void")) continue;
    std::size_t k = skipSpace(text, at + 4);
    if (k >= text.size() || text[k] != '(') continue;
    k = skipSpace(text, k + 1);
    if (wordAt(text, k, "void")) k = skipSpace(text, k + 4);
    if (k >= text.size() || text[k] != ')') continue;
    k = skipSpace(text, k + 1);
    if (k < text.size() && text[k] == '{') return k + 1;
  }
  return std::string::npos;
}

std::vector<GlslStatement> mainStatements(const std::string& source) {
  const std::string text = withoutComments(source);
  const std::size_t body = mainBody(text);
  if (body == std::string::npos) return {};
  std::vector<GlslStatement> out;
  int braces = 1, parens = 0;
  std::size_t start = body;
  for (std::size_t k = start; k < text.size() && braces > 0; ++k) {
    const char c = text[k];
    if (c == '(') ++parens;
    if (c == ')') --parens;
    if (parens > 0) continue;  // a for loop's header is not three statements
    if (c == '{' || c == '}') {
      // A block's header (`if (x)`, `else`) is no statement: start afresh.
      braces += c == '{' ? 1 : -1;
      start = k + 1;
      continue;
    }
    if (c != ';') continue;
    const std::string body = text.substr(start, k - start);
    const std::size_t first = body.find_first_not_of(" \t\r\n");
    if (first != std::string::npos)
      out.push_back({body.substr(first), lineAt(text, start + first), lineAt(text, k), braces - 1});
    start = k + 1;
  }
  return out;
}

std::vector<std::string> identifiersIn(const std::string& text) {
  std::vector<std::string> out;
  for (std::size_t k = 0; k < text.size();) {
    if (!identifierChar(text[k]) || std::isdigit(static_cast<unsigned char>(text[k]))) {
      // Skip a number whole (1.0e5, 2u) so its letters are not identifiers.
      if (std::isdigit(static_cast<unsigned char>(text[k])))
        while (k < text.size() && (identifierChar(text[k]) || text[k] == '.')) ++k;
      else
        ++k;
      continue;
    }
    // A swizzle or field after `.` is not a variable.
    const bool member = k > 0 && text[k - 1] == '.';
    std::size_t end = k;
    while (end < text.size() && identifierChar(text[end])) ++end;
    std::string word = text.substr(k, end - k);
    if (!member && std::find(out.begin(), out.end(), word) == out.end()) out.push_back(word);
    k = end;
  }
  return out;
}

}  // namespace snell
