#include "runner/failure_report.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <regex>
#include <sstream>

#include "core/glsl_declarations.h"
#include "core/pixel_mask.h"

namespace snell {
namespace {

std::string components(const float* data, int count) {
  std::vector<std::string> parts;
  for (int k = 0; k < count; ++k) parts.push_back(fmt::format("{:.9g}", data[k]));
  return count == 1 ? parts[0] : fmt::format("({})", fmt::join(parts, ", "));
}

}  // namespace

// Matrices and samplers are left out: they are the scene's, the same for
// every sample, and would bury the values that differ.
std::string sampleInputs(const AttributeMap& inputs, const UniformMap& uniforms,
                         std::size_t vertex) {
  std::vector<std::string> parts;
  for (const auto& [name, stream] : inputs)
    if (vertex < stream.vertexCount())
      parts.push_back(
          fmt::format("{} = {}", name,
                      components(&stream.data[vertex * stream.components], stream.components)));
  for (const auto& [name, value] : uniforms)
    if (value.data.size() <= 4 && !value.data.empty())
      parts.push_back(fmt::format(
          "{} = {}", name, components(value.data.data(), static_cast<int>(value.data.size()))));
  return fmt::format("{}", fmt::join(parts, ", "));
}

std::string constantsDisagreement(const Manifest& m, const ProgramSource& program) {
  // `const float Eta = 0.66;` with a plain number: what the oracle must share.
  static const std::regex constLine(
      R"(\bconst\s+float\s+([A-Za-z_]\w*)\s*=\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)[fF]?\s*;)");
  std::string text;
  struct Stage {
    const std::string& source;
    const std::string& file;
  };
  for (const Stage& stage :
       {Stage{program.vertex, program.vertexPath}, Stage{program.fragment, program.fragmentPath}}) {
    std::istringstream lines(withoutComments(stage.source));
    int lineNumber = 0;
    for (std::string line; std::getline(lines, line);) {
      ++lineNumber;
      std::smatch match;
      if (!std::regex_search(line, match, constLine)) continue;
      const auto given = m.constants.find(match[1].str());
      if (given == m.constants.end()) continue;
      const float listing = std::stof(match[2].str());
      if (static_cast<float>(given->second) == listing) continue;
      text += fmt::format(
          "{}:{}: the listing says `const float {} = {};` but {} gives {} = {:.9g}: the oracle "
          "computes with the manifest's value, so fix whichever is wrong first\n",
          stage.file, lineNumber, match[1].str(), match[2].str(), m.path.filename().string(),
          match[1].str(), given->second);
    }
  }
  return text;
}

int lineAssigning(const std::string& source, const std::string& name) {
  const std::regex assignment("\\b" + name + R"((\.[xyzwrgba]+)?\s*([-+*/]?=)(?!=))");
  std::istringstream lines(withoutComments(source));
  int last = 0;
  int lineNumber = 0;
  for (std::string line; std::getline(lines, line);) {
    ++lineNumber;
    std::smatch match;
    if (std::regex_search(line, match, assignment) && match[2].str() != "==") last = lineNumber;
  }
  return last;
}

// A check that examined nothing is no pass: a capture the spec leaves
// undefined everywhere (or beyond the manifest's max_undefined), or an image
// comparison that compared no pixel.
std::string nothingCheckedReasons(const Manifest& m, const CaseResult& result) {
  std::string reasons;
  for (const VaryingCheck& v : result.varyings) {
    const std::size_t all = v.checked + v.undefined;
    if (v.checked == 0) {
      reasons += fmt::format("{}: nothing checked: the spec leaves all {} components undefined\n",
                             v.name, all);
    } else if (static_cast<double>(v.undefined) >
               m.maxUndefinedFraction * static_cast<double>(all)) {
      reasons += fmt::format(
          "{}: the spec leaves {} of {} components ({:.2f}%) undefined, more than max_undefined = "
          "{} allows; change the scene, or raise max_undefined in {} if the listing means it\n",
          v.name, v.undefined, all, 100.0 * static_cast<double>(v.undefined) / all,
          m.maxUndefinedFraction, m.path.filename().string());
    }
  }
  for (const ImageComparison& image : result.images) {
    if (!image.problem.empty()) continue;
    if (image.compared == 0) {
      reasons +=
          fmt::format("image against {}: nothing compared: every pixel is masked\n", image.against);
      continue;
    }
    // The object's pixels where the listing is undefined are masked; the
    // background is compared all the same, so an image whose object is all
    // undefined would pass on its background alone. max_undefined holds
    // for pixels as for components.
    std::size_t all = image.compared, undefined = 0;
    for (const auto& [reason, count] : image.masked) {
      all += count;
      if (reason == pixelMaskName(PixelMask::Undefined)) undefined += count;
    }
    if (static_cast<double>(undefined) > m.maxUndefinedFraction * static_cast<double>(all))
      reasons += fmt::format(
          "image against {}: the spec leaves {} of {} pixels ({:.2f}%) undefined, more than "
          "max_undefined = {} allows; change the scene, or raise max_undefined in {} if the "
          "listing means it\n",
          image.against, undefined, all, 100.0 * static_cast<double>(undefined) / all,
          m.maxUndefinedFraction, m.path.filename().string());
  }
  return reasons;
}

std::string describeVertexFailures(const Manifest& m, const ProgramSource& program,
                                   const ResolvedBindings& bindings,
                                   const std::vector<VaryingCheck>& checks) {
  std::string text;
  for (const VaryingCheck& v : checks) {
    if (!v.failed) continue;
    const int line = lineAssigning(program.vertex, v.name);
    text += fmt::format("{}: {} of {} components outside the spec interval{}; worst first:\n",
                        v.name, v.failed, v.checked,
                        line ? fmt::format(" (assigned at {}:{})", program.vertexPath, line) : "");
    for (const ComponentFailure& f : v.worstFailures)
      text += fmt::format(
          "  vertex {} [{}]: got {:.9g}, exact {:.9g}, allowed [{:.9g}, {:.9g}]{}, slack {}\n"
          "    inputs: {}\n",
          f.vertex, f.component, f.observed, f.reference, f.lo, f.hi,
          f.ways > 1 ? fmt::format(" (nearest of {} ways)", f.ways) : "",
          std::isfinite(f.slack) ? fmt::format("{:.3g}", f.slack) : "inf",
          sampleInputs(bindings.attributes, bindings.uniforms, f.vertex));
  }
  if (text.empty()) return text;
  return constantsDisagreement(m, program) + text;
}

}  // namespace snell
