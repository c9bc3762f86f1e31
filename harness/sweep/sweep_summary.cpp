#include "sweep/sweep_summary.h"

#include <algorithm>
#include <map>
#include <tuple>

namespace snell::sweep {

std::vector<BreakGroup> groupBreaks(const SweepResult& result) {
  using Key = std::tuple<std::string, std::string, std::string, std::string, std::string>;
  std::map<Key, BreakGroup> groups;
  auto add = [&](const Break& b, const std::string& input, double angle, double eta) {
    const Key key{b.function, b.backend, input, b.kind, breakClassName(b.cls)};
    auto [it, fresh] = groups.try_emplace(key);
    BreakGroup& g = it->second;
    if (fresh) {
      g = {b.function, b.backend, input, b.kind, breakClassName(b.cls), 0, angle, angle, eta, eta};
    }
    ++g.count;
    g.angleMin = std::min(g.angleMin, angle);
    g.angleMax = std::max(g.angleMax, angle);
    g.etaMin = std::min(g.etaMin, eta);
    g.etaMax = std::max(g.etaMax, eta);
  };
  for (const Break& b : result.breaks) {
    const SweepPoint& p = result.points[b.point];
    add(b, p.input, p.angleDegrees, p.eta);
  }
  for (const Break& b : result.methodBreaks) {
    const MethodSample& s = result.methodSamples[b.point];
    add(b, sideName(s.eta), s.angleDegrees, s.eta);
  }
  std::vector<BreakGroup> out;
  for (auto& [key, group] : groups) out.push_back(group);
  return out;
}

}  // namespace snell::sweep
