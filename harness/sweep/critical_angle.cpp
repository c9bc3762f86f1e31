#include "sweep/critical_angle.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>

#include "oracle/physics/interface_angles.h"

namespace snell::sweep {
namespace {

bool isZero(const Observation& o) {
  return o.answered &&
         std::all_of(o.value.begin(), o.value.end(), [](double x) { return x == 0.0; });
}

}  // namespace

bool bothWaysAllowed(const Observation& oracle) {
  return !oracle.lo.empty() && oracle.lo[0] <= 0.0 && oracle.hi[0] >= 0.5;
}

std::vector<CriticalAngle> criticalAngles(const std::vector<SweepPoint>& points,
                                          const BackendSweep& oracle, const BackendSweep& sweep) {
  std::map<double, std::vector<std::size_t>> series;
  for (std::size_t k = 0; k < points.size(); ++k)
    if (points[k].input == "grid" && points[k].call.fn == "refract" && points[k].eta > 1)
      series[points[k].eta].push_back(k);
  std::vector<CriticalAngle> found;
  for (auto& [eta, members] : series) {
    std::sort(members.begin(), members.end(), [&](std::size_t a, std::size_t b) {
      return points[a].angleDegrees < points[b].angleDegrees;
    });
    CriticalAngle c;
    c.backend = sweep.backend;
    c.eta = eta;
    c.closedFormDegrees = physics::criticalAngleDegrees(eta, 1.0);
    const double tangent = std::tan(c.closedFormDegrees * std::numbers::pi / 180.0);
    c.inputRoundingDegrees = std::ldexp(tangent + 1.0 / tangent, -24) * 180.0 / std::numbers::pi;
    c.firstZeroDegrees = std::numeric_limits<double>::infinity();
    c.lastRefractedDegrees = -1;
    for (std::size_t k : members) {
      const Observation& o = sweep.points[k];
      const double angle = points[k].angleDegrees;
      if (!o.answered) continue;
      const bool zero = isZero(o);
      if (zero) c.firstZeroDegrees = std::min(c.firstZeroDegrees, angle);
      if (!zero) c.lastRefractedDegrees = std::max(c.lastRefractedDegrees, angle);
      if (std::abs(angle - c.closedFormDegrees) <= c.inputRoundingDegrees) continue;
      if (bothWaysAllowed(oracle.points[k])) {
        c.specBandDegrees = std::max(c.specBandDegrees, std::abs(angle - c.closedFormDegrees));
        continue;
      }
      const bool beyond = angle > c.closedFormDegrees;
      if (zero != beyond) ++c.wrongSide;
    }
    c.foundDegrees = 0.5 * (c.firstZeroDegrees + c.lastRefractedDegrees);
    c.resolutionDegrees = c.firstZeroDegrees - c.lastRefractedDegrees;
    c.agrees = c.wrongSide == 0 && c.resolutionDegrees > 0 && std::isfinite(c.resolutionDegrees) &&
               std::abs(c.foundDegrees - c.closedFormDegrees) <=
                   0.5 * c.resolutionDegrees + c.specBandDegrees + c.inputRoundingDegrees;
    found.push_back(c);
  }
  return found;
}

}  // namespace snell::sweep
