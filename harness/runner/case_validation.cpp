#include "runner/case_validation.h"

#include <fmt/format.h>

#include "core/errors.h"
#include "core/manifest_check.h"
#include "core/scene_file.h"
#include "oracle/vertex_oracle.h"
#include "runner/checks/check_kind.h"
#include "runner/run_helpers.h"

namespace snell {
void validateCase(const Case& c, SceneCache& scenes) {
  const Manifest& m = *c.manifest;
  requireKnownChecks(c);
  const ProgramSource program = loadProgram(m);
  const Scene* scene = nullptr;
  try {
    scene = &scenes.get(c.spec.scene);
  } catch (const UsageError& error) {
    // A broken scene file names its own place; an unknown scene is the case's.
    const std::string what = error.what();
    if (what.find(".toml:") < what.find(' ')) throw;
    manifestErrorAt(m, c.spec.line, what);
  }
  const ResolvedBindings bindings = resolveBindings(m, *scene);
  checkManifestAgainstProgram(m, program, bindings);
  if (!m.oracle.empty()) {
    try {
      makeVertexOracle(m.oracle);  // an unknown name throws
    } catch (const UsageError& error) {
      manifestErrorAt(m, m.oracleLine, error.what());
    }
  }
  if (m.expect == Expectation::CompileError) return;  // nothing runs but the compiler
  for (const auto& kind : checkKinds())
    if (c.spec.has(kind->name())) kind->validate(c, program, *scene);
}

void validateCases(const std::vector<Case>& cases, const std::string& shaders) {
  SceneCache scenes(sceneSearchPath(shaders));
  for (const Case& c : cases) validateCase(c, scenes);
}

}  // namespace snell
