#include "core/glsl_declarations.h"

#include <cctype>
#include <set>

namespace snell {
std::string withoutComments(const std::string& source) {
  std::string out = source;
  for (std::size_t k = 0; k + 1 < out.size(); ++k) {
    if (out[k] == '/' && out[k + 1] == '/') {
      while (k < out.size() && out[k] != '\n') out[k++] = ' ';
    } else if (out[k] == '/' && out[k + 1] == '*') {
      std::size_t end = out.find("*/", k + 2);
      end = end == std::string::npos ? out.size() : end + 2;
      for (; k < end; ++k)
        if (out[k] != '\n') out[k] = ' ';
      --k;
    }
  }
  return out;
}

namespace {

bool identifierChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

}  // namespace

std::vector<GlslDeclaration> readGlobalDeclarations(const std::string& source) {
  static const std::set<std::string> kQualifiers = {"uniform", "in", "out", "attribute", "varying"};
  static const std::set<std::string> kSkipped = {"flat",    "smooth",  "noperspective", "centroid",
                                                 "highp",   "mediump", "lowp",          "invariant",
                                                 "const"};
  const std::string text = withoutComments(source);
  std::vector<GlslDeclaration> out;
  int depth = 0, line = 1;
  std::vector<std::pair<std::string, int>> statement;  // tokens of the current global statement
  auto finishStatement = [&] {
    std::size_t k = 0;
    while (k < statement.size() && (kSkipped.count(statement[k].first) ||
                                    statement[k].first.rfind("layout(", 0) == 0))
      ++k;
    if (k < statement.size() && kQualifiers.count(statement[k].first)) {
      const std::string qualifier = statement[k].first;
      ++k;
      while (k < statement.size() && kSkipped.count(statement[k].first)) ++k;
      if (k + 1 < statement.size()) {
        const std::string type = statement[k].first;
        for (++k; k < statement.size(); ++k)
          if (statement[k].first != ",")
            out.push_back({qualifier, type, statement[k].first, statement[k].second});
      }
    }
    statement.clear();
  };
  for (std::size_t k = 0; k < text.size(); ++k) {
    const char c = text[k];
    if (c == '\n') ++line;
    if (c == '#') {  // preprocessor line
      while (k < text.size() && text[k] != '\n') ++k;
      ++line;
      continue;
    }
    if (c == '{') { ++depth; statement.clear(); continue; }
    if (c == '}') { --depth; statement.clear(); continue; }
    if (depth != 0) continue;
    if (c == ';') { finishStatement(); continue; }
    if (c == ',') { statement.push_back({",", line}); continue; }
    if (c == '[' || c == '=' || c == '(') {
      // An array size, an initialiser or a function: skip to the statement's end
      // for declarations of interest, keeping layout(...) as one token.
      if (c == '(' && !statement.empty() && statement.back().first == "layout") {
        const std::size_t end = text.find(')', k);
        statement.back().first = "layout(";
        k = end == std::string::npos ? text.size() : end;
        continue;
      }
      if (c == '(') statement.clear();
      while (k + 1 < text.size() && text[k + 1] != ';' && text[k + 1] != ',' && text[k + 1] != '{') {
        if (text[k + 1] == '\n') ++line;
        ++k;
      }
      continue;
    }
    if (identifierChar(c)) {
      std::size_t end = k;
      while (end < text.size() && identifierChar(text[end])) ++end;
      statement.push_back({text.substr(k, end - k), line});
      k = end - 1;
    }
  }
  return out;
}

}  // namespace snell
