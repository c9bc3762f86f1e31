#include "compare/slack.h"

#include <cmath>
#include <limits>

namespace snell {

double slack(double observed, double reference, double lo, double hi) {
  constexpr double kOutside = std::numeric_limits<double>::infinity();
  if (std::isnan(observed)) return kOutside;
  if (observed == reference) return 0.0;
  const double allowed = observed > reference ? hi - reference : reference - lo;
  if (!(allowed > 0)) return kOutside;  // no room on that side, or a malformed interval
  return std::abs(observed - reference) / allowed;
}

bool withinSpec(double observed, double lo, double hi) {
  return !std::isnan(observed) && lo <= observed && observed <= hi;
}

}  // namespace snell
