#pragma once
// Backend vs oracle for read-back vectors: every component must lie in the
// interval the precision rules allow for the listing's own expression.
#include <cstddef>
#include <string>
#include <vector>

#include "core/values.h"
#include "oracle/vertex_oracle.h"

namespace snell {

struct ComponentFailure {
  std::size_t vertex = 0;
  int component = 0;
  float observed = 0;
  double reference = 0, lo = 0, hi = 0, slack = 0;
};

struct VaryingCheck {
  std::string name;
  std::size_t checked = 0;    // components held against an interval
  std::size_t undefined = 0;  // components the spec leaves undefined: not gated
  std::size_t failed = 0;
  double worstSlack = 0;      // over the checked components
  std::size_t worstVertex = 0;
  std::vector<ComponentFailure> firstFailures;  // at most kFailuresKept, in vertex order
  static constexpr std::size_t kFailuresKept = 8;
};

// Throws std::invalid_argument when the two do not describe the same
// varying (name, component count or vertex count differ): that is a harness
// bug, never a driver result.
VaryingCheck checkVarying(const OracleVarying& expected, const CapturedVarying& observed);

}  // namespace snell
