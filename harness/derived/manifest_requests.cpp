#include "derived/manifest_requests.h"

#include <algorithm>
#include <string>

#include "core/glsl_declarations.h"

namespace snell::derived {

ShaderSource stageSource(const Manifest& m, Stage stage) {
  const ProgramSource program = loadProgram(m);
  if (stage == Stage::Vertex) return {program.vertexPath, program.vertex, Stage::Vertex};
  return {program.fragmentPath, program.fragment, Stage::Fragment};
}

std::vector<OutputRequest> captureRequests(const Manifest& m, Stage stage) {
  std::vector<OutputRequest> wanted;
  if (stage == Stage::Vertex) {
    for (const std::string& name : m.captureVertex) wanted.push_back({name, 0});
    return wanted;
  }
  const auto declarations = readGlobalDeclarations(loadProgram(m).fragment);
  for (const FragmentCapture& capture : m.captureFragment) {
    const bool input = std::any_of(declarations.begin(), declarations.end(), [&](const auto& d) {
      return d.name == capture.name && (d.qualifier == "in" || d.qualifier == "varying");
    });
    if (!input) wanted.push_back({capture.name, capture.line});
  }
  return wanted;
}

}  // namespace snell::derived
