#include "runner/listing_oracles.h"

#include <fmt/format.h>

#include "core/build_id.h"
#include "core/errors.h"
#include "derived/derived_drawing.h"
#include "derived/derived_vertex_oracle.h"
#include "derived/manifest_requests.h"
#include "oracle/reference/reference_image.h"
#include "runner/run_helpers.h"

namespace snell {
namespace {

derived::Stage derivedStage(CaptureStage stage) {
  return stage == CaptureStage::Vertex ? derived::Stage::Vertex : derived::Stage::Fragment;
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
    const derived::ShaderSource source = derived::stageSource(m, derivedStage(stage));
    const std::vector<derived::OutputRequest> wanted =
        derived::captureRequests(m, derivedStage(stage));
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
  const derived::ShaderSource vertex = derived::stageSource(m, derived::Stage::Vertex);
  const derived::ShaderSource fragment = derived::stageSource(m, derived::Stage::Fragment);
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
