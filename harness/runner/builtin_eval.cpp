#include "runner/builtin_eval.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "compare/slack.h"
#include "core/errors.h"
#include "oracle/builtin_probe.h"
#include "runner/eval_line.h"
#include "runner/physics_eval_line.h"
#include "runner/probe_shader.h"

namespace snell {
namespace {

using nlohmann::json;

constexpr std::size_t kBatchLines = 8192;

struct Line {
  std::size_t number = 0;
  std::optional<BuiltinCall> call;  // empty when malformed or a physics line
  std::optional<json> physics;      // a physics line's answer
  std::string error;
  std::optional<BuiltinResult> oracle;
  std::vector<float> driver;
};

json finite(const std::vector<double>& values) {
  json out = json::array();
  for (double x : values)
    out.push_back(std::isfinite(x) ? json(x) : json(x > 0 ? "inf" : x < 0 ? "-inf" : "nan"));
  return out;
}

json wayJson(const BuiltinWay& way) {
  json out = {{"value", finite(way.value)}, {"lo", finite(way.lo)}, {"hi", finite(way.hi)}};
  if (std::find(way.undefined.begin(), way.undefined.end(), true) != way.undefined.end())
    out["undefined"] = way.undefined;
  return out;
}

// One draw for all lines of the batch that share a function and a width.
void runOnDriver(std::vector<Line>& lines, Backend& backend) {
  std::map<std::pair<std::string, int>, std::vector<Line*>> groups;
  for (Line& line : lines)
    if (line.call) groups[{line.call->fn, static_cast<int>(line.call->I.size())}].push_back(&line);
  for (auto& [key, members] : groups) {
    const auto& [fn, width] = key;
    CaptureJob job;
    job.program = builtinProbeProgram(fn, width);
    job.varyings = {"R"};
    job.vertexCount = members.size();
    AttributeStream I{"I", width, {}}, N{"N", width, {}}, eta{"eta", 1, {}};
    for (const Line* line : members) {
      I.data.insert(I.data.end(), line->call->I.begin(), line->call->I.end());
      N.data.insert(N.data.end(), line->call->N.begin(), line->call->N.end());
      eta.data.push_back(line->call->eta);
    }
    job.attributes = {{"I", I}, {"N", N}};
    if (fn == "refract") job.attributes["eta"] = eta;
    const CaptureOutcome outcome = backend.captureVertexOutputs(job);
    if (!outcome.compile.ok)
      throw SetupError(fmt::format("the {} probe shader did not compile on {}: {}", fn,
                                   backend.name(), outcome.compile.log));
    const std::vector<float>& values = outcome.varyings.at(0).data;
    for (std::size_t k = 0; k < members.size(); ++k)
      members[k]->driver.assign(values.begin() + k * width, values.begin() + (k + 1) * width);
  }
}

json answer(const Line& line, bool onDriver, PrecisionRules rules, EvalSummary& summary) {
  if (line.physics) {
    ++summary.answered;
    json out = {{"line", line.number}};
    out.update(*line.physics);
    return out;
  }
  if (!line.call) {
    ++summary.malformed;
    return {{"line", line.number}, {"error", line.error}};
  }
  ++summary.answered;
  const BuiltinResult& oracle = *line.oracle;
  json out = {{"line", line.number}, {"fn", line.call->fn}, {"rules", precisionRulesName(rules)}};
  if (!onDriver) {
    out["value"] = finite(oracle.value);
  } else {
    // Judged as a whole vector against the way it fits (or comes nearest).
    const bool within = oracle.allows(line.driver);
    const BuiltinWay& way = oracle.nearestWay(line.driver);
    double worst = 0;
    for (std::size_t c = 0; c < line.driver.size(); ++c)
      if (!way.undefined[c])
        worst = std::max(worst, slack(line.driver[c], way.value[c], way.lo[c], way.hi[c]));
    if (!within) ++summary.outsideSpec;
    out["value"] = finite(std::vector<double>(line.driver.begin(), line.driver.end()));
    out["exact"] = finite(oracle.value);
    out["within_spec"] = within;
    out["slack"] = std::isfinite(worst) ? json(worst) : json("inf");
  }
  out["lo"] = finite(oracle.lo);
  out["hi"] = finite(oracle.hi);
  if (std::find(oracle.undefined.begin(), oracle.undefined.end(), true) != oracle.undefined.end())
    out["undefined"] = oracle.undefined;
  if (oracle.ways.size() > 1) {
    json ways = json::array();
    for (const BuiltinWay& w : oracle.ways) ways.push_back(wayJson(w));
    out["alternatives"] = ways;
  }
  return out;
}

void flushBatch(std::vector<Line>& lines, std::ostream& out, Backend* backend, PrecisionRules rules,
                EvalSummary& summary) {
  for (Line& line : lines)
    if (line.call) line.oracle = evaluateBuiltin(*line.call, rules);
  if (backend) runOnDriver(lines, *backend);
  for (const Line& line : lines)
    out << answer(line, backend != nullptr, rules, summary).dump() << '\n';
  out.flush();
  lines.clear();
}

}  // namespace

PrecisionRules precisionRulesForApi(const std::string& api) {
  return api == "Vulkan" ? PrecisionRules::Vulkan : PrecisionRules::Glsl;
}

EvalSummary evaluateLines(std::istream& in, std::ostream& out, Backend* backend,
                          PrecisionRules rules) {
  EvalSummary summary;
  std::vector<Line> batch;
  std::string text;
  std::size_t number = 0;
  while (std::getline(in, text)) {
    ++number;
    if (text.find_first_not_of(" \t\r") == std::string::npos) continue;
    Line line;
    line.number = number;
    try {
      const json object = json::parse(text);
      if (!isPhysicsCall(object)) {
        line.call = parseEvalObject(object);
      } else if (backend) {
        throw UsageError(fmt::format(
            "{} is answered by the physics reference, not by a driver: run it with --backend "
            "oracle",
            object.at("fn").get<std::string>()));
      } else {
        line.physics = evaluatePhysicsCall(object);
      }
    } catch (const json::exception& error) {
      line.error = fmt::format("line {}: not valid JSON ({})", number, error.what());
    } catch (const UsageError& error) {
      line.error = fmt::format("line {}: {}", number, error.what());
    }
    batch.push_back(std::move(line));
    if (batch.size() == kBatchLines) flushBatch(batch, out, backend, rules, summary);
  }
  flushBatch(batch, out, backend, rules, summary);
  return summary;
}

}  // namespace snell
