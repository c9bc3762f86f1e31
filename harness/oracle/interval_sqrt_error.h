#pragma once
// The bound on sqrt()'s error, shared by the general road
// (interval_builtins.cpp) and the shorter road for exact inputs
// (point_builtins.cpp). Internal to the oracle library.
#include <algorithm>
#include <cmath>

#include "oracle/fp32_bits.h"
#include "oracle/interval_float_sets.h"

namespace snell {

// sqrt(x) as 1.0 / inversesqrt(x), for an argument whose smallest value
// (computed or ideal) is `smallest`, whose error is `err` and whose largest
// float is `hi`, with the result's floats reaching from `lo` to `rootHi`.
inline double sqrtErrorBound(double smallest, double err, double hi, double lo, double rootHi) {
  using float_sets::up;
  // The argument's error through sqrt (sqrt(|a' - a|) at worst,
  // |a' - a| / (2 sqrt(m)) away from 0), plus the formula's own relative
  // error: inversesqrt's 2 ULP then the division's 2.5, each at most
  // 2^-23 of the value.
  const double m = std::max(0.0, smallest);
  const double propagated =
      m > 0.0 ? std::min(std::sqrt(err), err / (2.0 * std::sqrt(m))) : std::sqrt(err);
  // r = inversesqrt within 2 ULP, then 1 / r within 2.5 ULP. The first is
  // a relative error |delta| <= 2 gap(r) / r <= 2^-22 (r >= 2^-64 is
  // normal), which moves 1/r by |delta| / (1 - |delta|) of its value: a
  // bound relative to the result, whatever the smallest argument (at x =
  // 0 the result is exactly 0).
  const double sMax = float_sets::above(std::sqrt(hi));
  const double delta = 0x1p-22;
  const double own = up(sMax * delta / (1.0 - delta) + 2.5 * fp32_bits::gapAbove(rootHi) +
                        float_sets::flushError(lo, rootHi));
  return up(up(propagated) + own);
}

}  // namespace snell
