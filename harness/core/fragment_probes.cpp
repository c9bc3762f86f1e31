#include "core/fragment_probes.h"

#include <fmt/format.h>

#include <cctype>
#include <regex>
#include <string_view>

#include "core/errors.h"
#include "core/glsl_declarations.h"

namespace snell {
namespace {

// The source split into lines, each with its code: the same characters
// with comments blanked, so that braces and `main` in comments are ignored
// and columns agree between the two.
struct Lines {
  std::vector<std::string> text;  // without the line break
  std::vector<std::string> code;
  bool lastEndsWithBreak = true;
};

std::vector<std::string> splitAtBreaks(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  for (std::size_t at = text.find('\n'); at != std::string::npos; at = text.find('\n', start)) {
    lines.push_back(text.substr(start, at - start));
    start = at + 1;
  }
  if (start < text.size() || text.empty() || text.back() != '\n') lines.push_back(text.substr(start));
  return lines;
}

Lines splitLines(const std::string& source) {
  return {splitAtBreaks(source), splitAtBreaks(withoutComments(source)),
          !source.empty() && source.back() == '\n'};
}

struct Position {
  std::size_t line = 0;
  std::size_t column = 0;
};

struct MainBody {
  Position declaration;  // start of `void main`
  Position open;         // its `{`
  Position close;        // the matching `}`
};

MainBody findMain(const Lines& lines, const std::string& path) {
  static const std::regex kMain(R"(\bvoid\s+main\s*\()");
  MainBody body;
  bool found = false;
  for (std::size_t l = 0; l < lines.code.size() && !found; ++l) {
    std::smatch match;
    if (std::regex_search(lines.code[l], match, kMain)) {
      body.declaration = {l, static_cast<std::size_t>(match.position(0))};
      found = true;
    }
  }
  if (!found) throw UsageError(fmt::format("{}: no `void main(` to read values from", path));
  int depth = 0;
  bool opened = false;
  for (std::size_t l = body.declaration.line; l < lines.code.size(); ++l) {
    const std::size_t from = l == body.declaration.line ? body.declaration.column : 0;
    for (std::size_t c = from; c < lines.code[l].size(); ++c) {
      if (lines.code[l][c] == '{') {
        if (!opened) body.open = {l, c};
        opened = true;
        ++depth;
      } else if (lines.code[l][c] == '}' && opened && --depth == 0) {
        body.close = {l, c};
        return body;
      }
    }
  }
  throw UsageError(fmt::format("{}:{}: main() has no closing brace", path,
                               body.declaration.line + 1));
}

std::string asVec4(const FragmentProbe& probe) {
  switch (probe.type) {
    case ValueType::Float: return fmt::format("vec4(({}), 0.0, 0.0, 1.0)", probe.expression);
    case ValueType::Vec2: return fmt::format("vec4(({}), 0.0, 1.0)", probe.expression);
    case ValueType::Vec3: return fmt::format("vec4(({}), 1.0)", probe.expression);
    default:
      throw UsageError(fmt::format("probe `{}`: only float, vec2 and vec3 can be read back",
                                   probe.expression));
  }
}

std::string target(std::size_t index, ProbeOutputStyle style) {
  return style == ProbeOutputStyle::FragData ? fmt::format("gl_FragData[{}]", index + 1)
                                             : probeOutputName(index);
}

// Where code ends on a line: before a trailing comment and white space.
std::size_t codeEnd(const std::string& code) {
  std::size_t end = code.size();
  while (end > 0 && std::isspace(static_cast<unsigned char>(code[end - 1]))) --end;
  return end;
}

std::string replaceFragColor(const std::string& text) {
  static const std::regex kFragColor(R"(\bgl_FragColor\b)");
  return std::regex_replace(text, kFragColor, "gl_FragData[0]");
}

}  // namespace

constexpr std::string_view kProbePrefix = "snell_probe_";

std::string probeOutputName(std::size_t index) {
  return fmt::format("{}{}", kProbePrefix, index + 1);
}

std::optional<int> probeOutputLocation(const std::string& name) {
  if (name.rfind(kProbePrefix, 0) != 0) return std::nullopt;
  const std::string digits = name.substr(kProbePrefix.size());
  // A manifest reads back at most 7 values, so a location is one digit.
  if (digits.size() != 1 || digits[0] < '1' || digits[0] > '9') return std::nullopt;
  return digits[0] - '0';
}

ProbeOutputStyle probeOutputStyleFor(const std::string& source) {
  static const std::regex kLegacyOutput(R"(\bgl_Frag(Color|Data)\b)");
  const Lines lines = splitLines(source);
  for (const std::string& code : lines.code)
    if (std::regex_search(code, kLegacyOutput)) return ProbeOutputStyle::FragData;
  return ProbeOutputStyle::Outputs;
}

std::string insertFragmentProbes(const std::string& source, const std::string& path,
                                 const std::vector<FragmentProbe>& probes, ProbeOutputStyle style) {
  if (probes.empty()) return source;
  Lines lines = splitLines(source);
  const MainBody body = findMain(lines, path);

  // Appended at the end of a line's code, so every published line keeps its
  // number and diagnostics still point at the file.
  std::vector<std::string> appended(lines.text.size());
  for (std::size_t k = 0; k < probes.size(); ++k) {
    const FragmentProbe& probe = probes[k];
    const std::size_t l = static_cast<std::size_t>(probe.line) - 1;
    if (probe.line < 1 || l >= lines.text.size())
      throw UsageError(fmt::format("{}:{}: no such line (the file has {}); `line` of capture "
                                   "`{}` must be a line of the fragment file",
                                   path, probe.line, lines.text.size(), probe.expression));
    if (l < body.open.line || l >= body.close.line)
      throw UsageError(fmt::format("{}:{}: capture `{}` is read after this line, which is not "
                                   "inside main() (lines {} to {}); give a line of main's body",
                                   path, probe.line, probe.expression, body.open.line + 2,
                                   body.close.line));
    const std::string& code = lines.code[l];
    const std::size_t end = codeEnd(code);
    if (end == 0 || code[end - 1] != ';')
      throw UsageError(fmt::format("{}:{}: capture `{}` is read after this line, which does not "
                                   "end a statement with `;`; give the line where the statement "
                                   "that computes it ends",
                                   path, probe.line, probe.expression));
    appended[l] += fmt::format(" {} = {};", target(k, style), asVec4(probe));
  }

  std::string initial;
  for (std::size_t k = 0; k < probes.size(); ++k)
    initial += fmt::format(" {} = vec4(0.0);", target(k, style));
  std::string declarations;
  if (style != ProbeOutputStyle::FragData)
    for (std::size_t k = 0; k < probes.size(); ++k)
      declarations += fmt::format("out vec4 {}; ", probeOutputName(k));

  std::string out;
  for (std::size_t l = 0; l < lines.text.size(); ++l) {
    std::string text = lines.text[l];
    const std::string& code = lines.code[l];
    if (!appended[l].empty()) {
      const std::size_t end = codeEnd(code);
      text.insert(end, appended[l]);
    }
    if (l == body.open.line) text.insert(body.open.column + 1, initial);
    if (l == body.declaration.line) text.insert(body.declaration.column, declarations);
    if (style == ProbeOutputStyle::FragData) text = replaceFragColor(text);
    out += text;
    if (l + 1 < lines.text.size() || lines.lastEndsWithBreak) out += '\n';
  }
  return out;
}

}  // namespace snell
