#include "runner/case_runner.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "core/errors.h"
#include "core/phase_clock.h"
#include "core/scene_file.h"
#include "runner/builtin_eval.h"
#include "runner/checks/check_kind.h"
#include "runner/failure_report.h"
#include "runner/run_helpers.h"

namespace snell {
namespace {

// The key manifests use for an API: "gl" or "vk".
std::string apiKey(const DriverInfo& driver) {
  return precisionRulesForApi(driver.api) == PrecisionRules::Vulkan ? "vk" : "gl";
}

}  // namespace

SceneCache::SceneCache() : searchPath_{builtInScenesDir()} {}

const Scene& SceneCache::get(const std::string& name) {
  auto it = scenes_.find(name);
  if (it == scenes_.end()) it = scenes_.emplace(name, makeScene(name, searchPath_)).first;
  return it->second;
}

CaseResult CaseRunner::run(const Case& c) {
  const auto start = std::chrono::steady_clock::now();
  // Vector results and reference images alike: computed, or read from the store.
  const auto counts = [&] {
    return std::pair{oracles_.evaluated() + references_.rendered() + references_.fromStore(),
                     oracles_.stored() + references_.fromStore()};
  };
  const auto before = counts();
  PhaseRecording phases;
  CaseResult result = runChecks(c);
  result.phases = phases.finish();
  const auto after = counts();
  result.oracleResults = static_cast<int>(after.first - before.first);
  result.oracleStored = static_cast<int>(after.second - before.second);
  result.seconds = secondsSince(start);
  return result;
}

CaseResult CaseRunner::runChecks(const Case& c) {
  const Manifest& m = *c.manifest;
  CaseResult result;
  result.caseId = c.id;
  result.backend = backend_.name();
  result.title = m.title;
  result.sourceFile = m.source.file;
  result.sourceWhere = m.source.where;
  result.driver = driver_;

  // Manifests name the API (gl, vk), whichever of its drivers runs the case.
  if (const auto reason = m.notSupported.find(apiKey(driver_)); reason != m.notSupported.end()) {
    result.status = Status::NotSupported;
    result.message = reason->second;
    return result;
  }
  if (std::string why = backend_.whyCannotRun(loadProgram(m)); !why.empty()) {
    result.status = Status::NotSupported;
    result.message = why;
    return result;
  }
  const ResolvedBindings bindings = resolveBindings(m, scenes_.get(c.spec.scene));
  result.vertices = bindings.vertexCount;
  try {
    if (m.expect == Expectation::CompileError) {
      runExpectedCompileError(c, result);
    } else {
      CheckEnvironment environment{backend_, driver_,     oracles_,
                                   scenes_,  references_, imageOptions_};
      for (const auto& kind : checkKinds())
        if (c.spec.has(kind->name()) && result.status != Status::CompileError)
          kind->run(c, bindings, environment, result);
    }
  } catch (const SetupError& error) {
    result.status = Status::Fail;
    result.message += fmt::format("backend error: {}\n", error.what());
  }
  if (result.status != Status::CompileError && result.status != Status::ExpectedCompileError)
    if (const std::string reasons = nothingCheckedReasons(m, result); !reasons.empty()) {
      result.status = worstOf(result.status, Status::Fail);
      result.message = reasons + result.message;
    }
  return result;
}

// A listing kept as published although it does not compile: it passes as
// ExpectedCompileError when the driver refuses it with the diagnostic the
// manifest pins (stage, line, pattern), and fails when the driver takes it
// or refuses it for another reason.
void CaseRunner::runExpectedCompileError(const Case& c, CaseResult& result) {
  const Manifest& m = *c.manifest;
  const auto backendStart = std::chrono::steady_clock::now();
  const ProgramSource program = loadProgram(m);
  const CompileOutcome outcome = [&] {
    const PhaseScope phase(Phase::Compile);
    return backend_.compile(program);
  }();
  result.backendSeconds += secondsSince(backendStart);
  result.compileLog = outcome.log;
  if (outcome.ok) {
    result.status = Status::Fail;
    result.message =
        "compiled, but the listing as published is expected not to compile "
        "(`expect = \"compile-error\"`)" +
        (outcome.log.empty() ? std::string() : ":\n" + outcome.log);
    return;
  }
  const auto pinned = m.expectedErrors.find(apiKey(driver_));
  if (pinned == m.expectedErrors.end()) {
    result.status = Status::ExpectedCompileError;
    result.message = "does not compile, as expected:\n" + outcome.log;
    return;
  }
  const ExpectedDiagnostic& want = pinned->second;
  const std::string file = want.stage == "vertex" ? m.vertexFile : m.fragmentFile;
  const auto matches = [&](const CompileDiagnostic& d) {
    return d.error && d.stage == want.stage && d.line == want.line &&
           d.message.find(want.pattern) != std::string::npos;
  };
  // The first error is the one pinned: errors after it may be consequences of
  // it, and an error before it means the text changed.
  const auto found = std::find_if(outcome.diagnostics.begin(), outcome.diagnostics.end(),
                                  [](const CompileDiagnostic& d) { return d.error; });
  if (found == outcome.diagnostics.end() || !matches(*found)) {
    result.status = Status::Fail;
    result.message = fmt::format(
        "does not compile, but not with the expected error: {} expects an error at {}:{}{} "
        "(manifest line {}); the compiler said:\n{}",
        m.path.filename().string(), file, want.line,
        want.pattern.empty() ? "" : fmt::format(" containing \"{}\"", want.pattern),
        want.manifestLine, outcome.log);
    return;
  }
  result.status = Status::ExpectedCompileError;
  result.message = fmt::format("does not compile, as expected: {}:{}: {}\n{}", file, found->line,
                               found->message, outcome.log);
}

}  // namespace snell
