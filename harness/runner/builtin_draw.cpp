#include "runner/builtin_draw.h"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <string>
#include <utility>

#include "compare/slack.h"
#include "core/errors.h"
#include "runner/probe_shader.h"

namespace snell {

void drawBuiltinCalls(std::span<const DrawnCall> calls, Backend& backend) {
  std::map<std::pair<std::string, int>, std::vector<const DrawnCall*>> groups;
  for (const DrawnCall& drawn : calls)
    groups[{drawn.call->fn, static_cast<int>(drawn.call->I.size())}].push_back(&drawn);
  for (auto& [key, members] : groups) {
    const auto& [fn, width] = key;
    CaptureJob job;
    job.program = builtinProbeProgram(fn, width);
    job.varyings = {"R"};
    job.vertexCount = members.size();
    AttributeStream I{"I", width, {}}, N{"N", width, {}}, eta{"eta", 1, {}};
    I.data.reserve(members.size() * static_cast<std::size_t>(width));
    N.data.reserve(members.size() * static_cast<std::size_t>(width));
    eta.data.reserve(members.size());
    for (const DrawnCall* drawn : members) {
      I.data.insert(I.data.end(), drawn->call->I.begin(), drawn->call->I.end());
      N.data.insert(N.data.end(), drawn->call->N.begin(), drawn->call->N.end());
      eta.data.push_back(drawn->call->eta);
    }
    job.attributes = {{"I", std::move(I)}, {"N", std::move(N)}};
    if (fn == "refract") job.attributes["eta"] = std::move(eta);
    const CaptureOutcome outcome = backend.captureVertexOutputs(job);
    if (!outcome.compile.ok)
      throw SetupError(fmt::format("the {} probe shader did not compile on {}: {}", fn,
                                   backend.name(), outcome.compile.log));
    const std::vector<float>& values = outcome.varyings.at(0).data;
    for (std::size_t k = 0; k < members.size(); ++k)
      members[k]->driver->assign(values.begin() + k * width, values.begin() + (k + 1) * width);
  }
}

DriverJudgement judgeDriverVector(const BuiltinResult& oracle, std::span<const float> driver) {
  DriverJudgement judgement;
  // Judged as a whole vector against the way it fits (or comes nearest).
  judgement.outside = !oracle.allows(driver);
  const BuiltinWay& nearest = oracle.nearestWay(driver);
  for (std::size_t c = 0; c < driver.size(); ++c)
    if (!nearest.undefined[c])
      judgement.worstSlack = std::max(
          judgement.worstSlack, slack(driver[c], nearest.value[c], nearest.lo[c], nearest.hi[c]));
  return judgement;
}

}  // namespace snell
