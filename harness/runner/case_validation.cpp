#include "runner/case_validation.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

#include "core/errors.h"
#include "core/manifest_check.h"
#include "core/scene_file.h"
#include "oracle/vertex_oracle.h"
#include "runner/fragment_vector_check.h"

namespace snell {
namespace {

[[noreturn]] void atLine(const Manifest& m, int line, const std::string& what) {
  throw UsageError(fmt::format("{}:{}: {}", m.path.string(), line, what));
}

// An oracle that does not compute a captured output would leave the worker
// with nothing to compare: said here, with the manifest line, instead.
void checkOracleComputesCaptures(const Manifest& m, const VertexOracle& oracle) {
  const std::vector<std::string> outputs = oracle.outputs();
  for (const std::string& name : m.captureVertex)
    if (std::find(outputs.begin(), outputs.end(), name) == outputs.end())
      atLine(m, m.captureLine,
             fmt::format("capture.vertex names `{}`, which oracle `{}` does not compute (it "
                         "computes {}); capture one of those or name another oracle",
                         name, m.oracle, fmt::join(outputs, ", ")));
}

}  // namespace

void validateCase(const Case& c, SceneCache& scenes) {
  const Manifest& m = *c.manifest;
  const ProgramSource program = loadProgram(m);
  const Scene* scene = nullptr;
  try {
    scene = &scenes.get(c.spec.scene);
  } catch (const UsageError& error) {
    // A broken scene file names its own place; an unknown scene is the case's.
    const std::string what = error.what();
    if (what.find(".toml:") < what.find(' ')) throw;
    atLine(m, c.spec.line, what);
  }
  const ResolvedBindings bindings = resolveBindings(m, *scene);
  checkManifestAgainstProgram(m, program, bindings);
  std::unique_ptr<VertexOracle> oracle;
  try {
    oracle = makeVertexOracle(m.oracle);
  } catch (const UsageError& error) {
    atLine(m, m.oracleLine, error.what());
  }
  if (m.expect == Expectation::CompileError) return;  // nothing runs but the compiler
  if (c.spec.has("vectors")) {
    checkOracleComputesCaptures(m, *oracle);
    try {
      checkFragmentCaptures(m, program, *scene);
    } catch (const UsageError& error) {
      // Errors about the program or the oracle carry their own place.
      const std::string what = error.what();
      if (what.rfind(m.path.string() + ":", 0) == 0 ||
          what.rfind(program.fragmentPath + ":", 0) == 0)
        throw;
      atLine(m, c.spec.line, what);
    }
  }
  if (c.spec.has("image")) {
    if (!scene->draws())
      atLine(m, c.spec.line,
             fmt::format("scene `{}` draws nothing; its cases check [\"vectors\"] only",
                         scene->name));
    if (!hasFragmentOracle(m.oracle))
      atLine(m, m.oracleLine,
             fmt::format("oracle `{}` has no fragment part, so the \"image\" check has no "
                         "reference",
                         m.oracle));
  }
}

void validateCases(const std::vector<Case>& cases, const std::string& shaders) {
  SceneCache scenes(sceneSearchPath(shaders));
  for (const Case& c : cases) validateCase(c, scenes);
}

}  // namespace snell
