#pragma once
// Backend vs oracle for read-back vectors: every component must lie in the
// interval the precision rules allow for the listing's own expression, and
// where a branch may go either way (OracleVarying::alternatives) all the
// components of a vector must fit the same way.
#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "core/values.h"
#include "core/expected_values.h"

namespace snell {

struct ComponentFailure {
  std::size_t vertex = 0;
  int component = 0;
  float observed = 0;
  double reference = 0, lo = 0, hi = 0, slack = 0;
  int ways = 1;  // alternatives the sample had; the values above are the nearest one's
};

// The slack distribution of a varying's checked components, for the
// tolerance report: bin k counts slacks in (kSlackBinUpper[k-1],
// kSlackBinUpper[k]]; bin 0 the exact results (slack 0). Above 1 is outside
// the spec. Quarter steps below 1/4 are log-spaced: most drivers sit there.
inline constexpr std::array<double, 8> kSlackBinUpper = {0.0, 1.0 / 64, 1.0 / 16, 0.25,
                                                         0.5, 1.0,      2.0,      1e300};
std::size_t slackBin(double slack);

struct VaryingCheck {
  std::string name;
  std::size_t checked = 0;    // components held against an interval
  std::size_t undefined = 0;  // components the spec leaves undefined: not gated
  std::size_t failed = 0;
  std::size_t withAlternatives = 0;  // samples held against two or more ways
  double worstSlack = 0;             // over the checked components
  std::size_t worstVertex = 0;
  std::array<std::size_t, kSlackBinUpper.size()> slackHistogram{};
  // The failures with the largest slack, worst first, at most kFailuresKept;
  // a failure identical to one kept (same component, value and interval) is
  // not kept twice.
  std::vector<ComponentFailure> worstFailures;
  static constexpr std::size_t kFailuresKept = 8;
};

// Throws std::invalid_argument when the two do not describe the same
// varying (name, component count or vertex count differ): that is a harness
// bug, never a driver result.
VaryingCheck checkVarying(const OracleVarying& expected, const CapturedVarying& observed);

}  // namespace snell
