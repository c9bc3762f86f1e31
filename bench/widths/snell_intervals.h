#pragma once
// What snell's oracle allows, in one shape for every oracle version: per
// sample, one or more ways (alternatives), each a box of components. This
// file is the tool's only contact with the oracle's API.
#include <cstddef>
#include <string>
#include <vector>

#include "core/values.h"
#include "oracle/precision_rules.h"

namespace snell::widths {

struct SnellWay {
  std::vector<double> lo, hi;
  std::vector<bool> undefined;
};

// The hull of the ways and the ways themselves (one when the oracle keeps no
// alternatives at this sample).
struct SnellSample {
  SnellWay hull;
  std::vector<SnellWay> ways;
  bool allows(const std::vector<float>& vector) const;
};

SnellSample snellBuiltin(const std::string& fn, const std::vector<float>& I,
                         const std::vector<float>& N, float eta, PrecisionRules rules);

struct ListingBindings {
  UniformMap uniforms;
  ConstantMap constants;
  AttributeMap attributes;
  std::size_t vertexCount = 0;
};

// [output][vertex], outputs in the oracle's order (its `visit` order).
std::vector<std::vector<SnellSample>> snellListing(const std::string& oracle,
                                                   const ListingBindings& bindings,
                                                   PrecisionRules rules);

// The oracle's output names, in the order snellListing gives them.
std::vector<std::string> snellListingOutputs(const std::string& oracle);

// Which oracle this tool was built against ("HEAD" or the commit given at
// configure time), for the report.
const char* snellOracleVersion();

}  // namespace snell::widths
