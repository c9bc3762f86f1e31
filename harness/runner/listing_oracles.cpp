#include "runner/listing_oracles.h"

#include <fmt/format.h>

#include <algorithm>

#include "core/build_id.h"
#include "core/errors.h"
#include "core/glsl_declarations.h"
#include "derived/derived_drawing.h"
#include "derived/derived_vertex_oracle.h"
#include "oracle/reference/reference_image.h"
#include "runner/run_helpers.h"

namespace snell {
namespace {

derived::ShaderSource stageSource(const Manifest& m, CaptureStage stage) {
  const ProgramSource program = loadProgram(m);
  if (stage == CaptureStage::Vertex)
    return {program.vertexPath, program.vertex, derived::Stage::Vertex};
  return {program.fragmentPath, program.fragment, derived::Stage::Fragment};
}

// The derived oracle's requests: the vertex captures at the end of main(),
// the fragment captures that are not the stage's inputs after their lines.
std::vector<derived::OutputRequest> requests(const Manifest& m, CaptureStage stage) {
  std::vector<derived::OutputRequest> wanted;
  if (stage == CaptureStage::Vertex) {
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

std::unique_ptr<VertexOracle> handWritten(const Manifest& m) {
  try {
    return makeVertexOracle(m.oracle);
  } catch (const UsageError& error) {
    manifestErrorAt(m, m.oracleLine, error.what());
  }
}

// The builds of the code an oracle runs: its own and the interval
// arithmetic's (the same executable, unless they ever move into libraries).
std::string codeBuild(const void* oracleCode) {
  const std::string own = buildIdContaining(oracleCode);
  const std::string intervals = buildIdContaining(reinterpret_cast<const void*>(&makeVertexOracle));
  return own.empty() || intervals.empty() ? "" : own + " " + intervals;
}

std::string handWrittenIdentity(const Manifest& m) {
  const std::string build = codeBuild(reinterpret_cast<const void*>(&makeVertexOracle));
  return build.empty() ? "" : fmt::format("hand-written {} build {}", m.oracle, build);
}

std::string derivedIdentity(const derived::ShaderSource& source,
                            const std::vector<derived::OutputRequest>& wanted) {
  const std::string build =
      codeBuild(reinterpret_cast<const void*>(&derived::makeDerivedVectorOracle));
  if (build.empty()) return "";
  std::string identity =
      fmt::format("derived build {} stage {} file {} ({} bytes)\n{}\n", build,
                  static_cast<int>(source.stage), source.file, source.text.size(), source.text);
  for (const derived::OutputRequest& r : wanted)
    identity += fmt::format("{} after line {}\n", r.name, r.afterLine);
  return identity;
}

}  // namespace

std::vector<NamedOracle> vectorOracles(const Manifest& m, CaptureStage stage) {
  std::vector<NamedOracle> oracles;
  if (!m.oracle.empty()) oracles.push_back({m.oracle, handWritten(m), handWrittenIdentity(m)});
  if (m.derivedOracle) {
    const derived::ShaderSource source = stageSource(m, stage);
    const std::vector<derived::OutputRequest> wanted = requests(m, stage);
    oracles.push_back({kDerivedOracleLabel, derived::makeDerivedVectorOracle(source, wanted),
                       derivedIdentity(source, wanted)});
  }
  return oracles;
}

DrawingOracles drawingOracles(const Manifest& m) {
  if (!m.oracle.empty() && (hasFragmentOracle(m.oracle) || !m.derivedOracle)) {
    if (!hasFragmentOracle(m.oracle))
      manifestErrorAt(
          m, m.oracleLine,
          fmt::format("oracle `{}` has no fragment part, so the \"image\" check has no "
                      "reference; add \"derived\" to `oracle` for one drawn from the listing",
                      m.oracle));
    return {m.oracle, handWritten(m), makeFragmentOracle(m.oracle), handWrittenIdentity(m)};
  }
  const derived::ShaderSource vertex = stageSource(m, CaptureStage::Vertex);
  const derived::ShaderSource fragment = stageSource(m, CaptureStage::Fragment);
  const std::string vertexIdentity = derivedIdentity(vertex, {});
  const std::string fragmentIdentity = derivedIdentity(fragment, {});
  return {kDerivedOracleLabel, derived::makeDerivedDrawingVertexOracle(vertex),
          derived::makeDerivedFragmentOracle(fragment),
          vertexIdentity.empty() || fragmentIdentity.empty()
              ? ""
              : "drawing\n" + vertexIdentity + fragmentIdentity};
}

std::string oracleLabel(const Manifest& m) {
  if (m.oracle.empty()) return kDerivedOracleLabel;
  return m.derivedOracle ? m.oracle + " + " + kDerivedOracleLabel : m.oracle;
}

}  // namespace snell
