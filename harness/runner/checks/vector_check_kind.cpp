#include "runner/checks/vector_check_kind.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/errors.h"
#include "core/phase_clock.h"
#include "oracle/vertex_oracle.h"
#include "runner/builtin_eval.h"
#include "runner/case_runner.h"
#include "runner/failure_report.h"
#include "runner/fragment_vector_check.h"
#include "runner/json_fields.h"
#include "runner/listing_oracles.h"
#include "runner/run_helpers.h"

namespace snell {
namespace {

// An oracle that does not compute a captured output would leave the worker
// with nothing to compare: said here, with the manifest line, instead.
void checkOracleComputesCaptures(const Manifest& m) {
  if (m.captureVertex.empty()) return;
  for (const NamedOracle& named : vectorOracles(m, CaptureStage::Vertex)) {
    const std::vector<std::string> outputs = named.oracle->outputs();
    for (const std::string& name : m.captureVertex)
      if (std::find(outputs.begin(), outputs.end(), name) == outputs.end())
        manifestErrorAt(
            m, m.captureLine,
            fmt::format("capture.vertex names `{}`, which oracle `{}` does not compute (it "
                        "computes {}); capture one of those or name another oracle",
                        name, named.label, fmt::join(outputs, ", ")));
  }
}

void runVertexOutputs(const Case& c, const ResolvedBindings& bindings, CheckEnvironment& env,
                      CaseResult& result) {
  const Manifest& m = *c.manifest;
  const std::vector<NamedOracle> oracles = vectorOracles(m, CaptureStage::Vertex);
  CaptureJob job{loadProgram(m), bindings.uniforms, bindings.attributes, m.captureVertex,
                 bindings.vertexCount};
  const auto backendStart = std::chrono::steady_clock::now();
  const CaptureOutcome outcome = env.backend.captureVertexOutputs(job);
  result.backendSeconds += secondsSince(backendStart);
  result.compileLog = outcome.compile.log;
  if (!outcome.compile.ok) {
    result.status = Status::CompileError;
    result.message = outcome.compile.log;
    return;
  }
  for (const NamedOracle& oracle : oracles) {
    double seconds = 0;
    const std::vector<OracleVarying>& expected =
        env.oracles.get(c, oracle, bindings, precisionRulesForApi(env.driver.api), &seconds);
    result.oracleSeconds += seconds;
    const PhaseScope comparing(Phase::Compare);
    std::vector<VaryingCheck> checks;
    for (std::size_t k = 0; k < expected.size(); ++k)
      checks.push_back(checkVarying(expected[k], outcome.varyings.at(k)));
    // With two oracles the second one's checks carry its label: the summary
    // and the failures say which oracle a value left.
    std::string failures = describeVertexFailures(m, job.program, bindings, checks);
    if (&oracle != &oracles.front()) {
      for (VaryingCheck& check : checks) check.name += " (" + oracle.label + ")";
      if (!failures.empty()) failures = "against oracle " + oracle.label + ":\n" + failures;
    } else if (oracles.size() > 1 && !failures.empty()) {
      failures = "against oracle " + oracle.label + ":\n" + failures;
    }
    result.message += failures;
    for (VaryingCheck& check : checks) result.varyings.push_back(std::move(check));
  }
  if (result.componentsFailed()) result.status = worstOf(result.status, Status::Fail);
}

void runFragmentValues(const Case& c, const ResolvedBindings& bindings, CheckEnvironment& env,
                       CaseResult& result) {
  const Scene& scene = env.scenes.get(c.spec.scene);
  const auto backendStart = std::chrono::steady_clock::now();
  FragmentVectorCheck check =
      checkFragmentVectors(env.backend, *c.manifest, scene, bindings, env.oracles);
  result.backendSeconds += secondsSince(backendStart) - check.oracleSeconds;
  result.oracleSeconds += check.oracleSeconds;
  if (!check.compiled) {
    result.status = Status::CompileError;
    result.compileLog = check.compileLog;
    result.message = check.compileLog;
    return;
  }
  result.vertices = check.pixels;
  for (VaryingCheck& varying : check.varyings) result.varyings.push_back(std::move(varying));
  if (result.componentsFailed() || !check.unwritten.empty())
    result.status = worstOf(result.status, Status::Fail);
  if (check.pixels == 0) {
    result.status = worstOf(result.status, Status::Fail);
    result.message += "no pixel wrote every value the oracle reads: nothing was checked\n";
  }
  result.message += check.unwritten + check.failures;
}

// "-" where nothing was held against an interval: 0.000 would read as a perfect match.
std::string slackCell(const CaseResult& r) {
  if (r.componentsChecked() == 0) return "-";
  const double s = r.worstSlack();
  return std::isfinite(s) ? fmt::format("{:.3f}", s) : "inf";
}

// The count and, where anything was read back, the fraction of components
// the spec leaves undefined (a manifest's max_undefined bounds it).
std::string undefinedCell(const CaseResult& r) {
  const std::size_t undefined = r.componentsUndefined();
  const std::size_t all = undefined + r.componentsChecked();
  if (all == 0) return "-";
  return fmt::format("{} ({:.1f}%)", undefined, 100.0 * static_cast<double>(undefined) / all);
}

std::string vectorsCell(const CaseResult& r) { return std::to_string(r.vectorsChecked()); }

}  // namespace

void VectorCheckKind::validate(const Case& c, const ProgramSource& program,
                               const Scene& scene) const {
  const Manifest& m = *c.manifest;
  checkOracleComputesCaptures(m);
  try {
    checkFragmentCaptures(m, program, scene);
  } catch (const UsageError& error) {
    // Errors about the program or the oracle carry their own place.
    const std::string what = error.what();
    if (what.rfind(m.path.string() + ":", 0) == 0 || what.rfind(program.fragmentPath + ":", 0) == 0)
      throw;
    manifestErrorAt(m, c.spec.line, what);
  }
}

void VectorCheckKind::run(const Case& c, const ResolvedBindings& bindings, CheckEnvironment& env,
                          CaseResult& result) const {
  const Manifest& m = *c.manifest;
  if (!m.captureVertex.empty()) runVertexOutputs(c, bindings, env, result);
  if (!m.captureFragment.empty() && result.status != Status::CompileError)
    runFragmentValues(c, bindings, env, result);
}

void VectorCheckKind::writeJson(const CaseResult& r, nlohmann::json& record) const {
  nlohmann::json varyings = nlohmann::json::array();
  for (const VaryingCheck& v : r.varyings) {
    nlohmann::json failures = nlohmann::json::array();
    for (const ComponentFailure& f : v.worstFailures)
      failures.push_back({{"vertex", f.vertex},
                          {"component", f.component},
                          {"observed", jsonNumber(f.observed)},
                          {"reference", f.reference},
                          {"lo", f.lo},
                          {"hi", f.hi},
                          {"slack", jsonNumber(f.slack)}});
    varyings.push_back({{"name", v.name},
                        {"checked", v.checked},
                        {"undefined", v.undefined},
                        {"failed", v.failed},
                        {"worst_slack", jsonNumber(v.worstSlack)},
                        {"worst_vertex", v.worstVertex},
                        {"slack_histogram", v.slackHistogram},
                        {"first_failures", failures}});
  }
  record["components_checked"] = r.componentsChecked();
  record["components_undefined"] = r.componentsUndefined();
  record["components_failed"] = r.componentsFailed();
  record["worst_slack"] = jsonNumber(r.worstSlack());
  record["varyings"] = varyings;
}

void VectorCheckKind::readJson(const nlohmann::json& j, CaseResult& r) const {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  for (const nlohmann::json& v : j.at("varyings")) {
    VaryingCheck check;
    check.name = v.at("name").get<std::string>();
    check.checked = jsonCount<std::size_t>(v.at("checked"));
    check.undefined = jsonCount<std::size_t>(v.at("undefined"));
    check.failed = jsonCount<std::size_t>(v.at("failed"));
    check.worstSlack = jsonNumberOr(v.at("worst_slack"), kInf);
    check.worstVertex = jsonCount<std::size_t>(v.at("worst_vertex"));
    if (v.contains("slack_histogram")) {  // absent from older records
      const nlohmann::json& bins = v.at("slack_histogram");
      if (!bins.is_array() || bins.size() != check.slackHistogram.size())
        throw nlohmann::json::type_error::create(
            302,
            "slack_histogram must hold " + std::to_string(check.slackHistogram.size()) + " counts",
            &bins);
      for (std::size_t k = 0; k < bins.size(); ++k)
        check.slackHistogram[k] = jsonCount<std::size_t>(bins[k]);
    }
    for (const nlohmann::json& f : v.at("first_failures"))
      check.worstFailures.push_back(
          {jsonCount<std::size_t>(f.at("vertex")), jsonCount<int>(f.at("component")),
           static_cast<float>(jsonNumberOr(f.at("observed"), std::nan(""))),
           f.at("reference").get<double>(), f.at("lo").get<double>(), f.at("hi").get<double>(),
           jsonNumberOr(f.at("slack"), kInf)});
    r.varyings.push_back(std::move(check));
  }
}

std::vector<SummaryColumn> VectorCheckKind::summaryColumns() const {
  return {{"vectors", 8, vectorsCell},
          {"undefined", 15, undefinedCell},
          {"worst slack", 11, slackCell}};
}

std::string VectorCheckKind::junitMessage(const CaseResult& r) const {
  const std::size_t failed = r.componentsFailed();
  if (failed == 0) return {};
  const auto worst = std::max_element(
      r.varyings.begin(), r.varyings.end(),
      [](const VaryingCheck& a, const VaryingCheck& b) { return a.worstSlack < b.worstSlack; });
  return fmt::format("{} of {} components outside the spec interval, worst slack {} in `{}`",
                     failed, r.componentsChecked(), slackCell(r), worst->name);
}

}  // namespace snell
