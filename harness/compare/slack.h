#pragma once
// Slack: how much of the allowed error a result used. 0 means the result
// equals the exact value, 1 means it sits on the edge of what the spec
// allows, above 1 means it is outside. Measured on the side the result
// fell, because the allowed interval is rarely symmetric.
//
// Inline: the comparison of a run calls both once per component read back
// (millions per suite), where a call was a fifth of the time.
#include <cmath>
#include <limits>

namespace snell {

inline double slack(double observed, double reference, double lo, double hi) {
  constexpr double kOutside = std::numeric_limits<double>::infinity();
  if (std::isnan(observed)) return kOutside;
  if (observed == reference) return 0.0;
  const double allowed = observed > reference ? hi - reference : reference - lo;
  if (!(allowed > 0)) return kOutside;  // no room on that side, or a malformed interval
  // An infinity where that side has no bound (an overflow the spec allows)
  // sits on its edge; inf / inf would be NaN, counted as outside.
  if (std::isinf(observed) && std::isinf(allowed)) return 1.0;
  return std::abs(observed - reference) / allowed;
}

inline bool withinSpec(double observed, double lo, double hi) {
  return !std::isnan(observed) && lo <= observed && observed <= hi;
}

}  // namespace snell
