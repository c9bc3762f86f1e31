#include "compare/vector_check.h"

#include <fmt/format.h>

#include <stdexcept>

#include "compare/slack.h"

namespace snell {

VaryingCheck checkVarying(const OracleVarying& expected, const CapturedVarying& observed) {
  if (expected.name != observed.name || expected.components != observed.components ||
      expected.reference.size() != observed.data.size() ||
      expected.lo.size() != observed.data.size() || expected.hi.size() != observed.data.size() ||
      expected.undefined.size() != observed.data.size())
    throw std::invalid_argument(fmt::format(
        "oracle output {} ({} x {}) does not match captured {} ({} values)", expected.name,
        expected.components, expected.reference.size(), observed.name, observed.data.size()));
  VaryingCheck check;
  check.name = expected.name;
  for (std::size_t k = 0; k < observed.data.size(); ++k) {
    if (expected.undefined[k]) {
      ++check.undefined;
      continue;
    }
    ++check.checked;
    const double value = observed.data[k];
    const double s = slack(value, expected.reference[k], expected.lo[k], expected.hi[k]);
    const std::size_t vertex = k / expected.components;
    if (s > check.worstSlack) {
      check.worstSlack = s;
      check.worstVertex = vertex;
    }
    if (!withinSpec(value, expected.lo[k], expected.hi[k])) {
      ++check.failed;
      if (check.firstFailures.size() < VaryingCheck::kFailuresKept)
        check.firstFailures.push_back({vertex, static_cast<int>(k % expected.components),
                                       observed.data[k], expected.reference[k], expected.lo[k],
                                       expected.hi[k], s});
    }
  }
  return check;
}

}  // namespace snell
