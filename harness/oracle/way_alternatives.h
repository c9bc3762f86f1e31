#pragma once
// The ways a sample's undecidable branches may go (oracle/branch_paths.h),
// recorded into the varyings as alternatives: shared by the hand-written
// listing oracles and the derived one.
#include <cstddef>
#include <vector>

#include "core/expected_values.h"
#include "oracle/interval.h"

namespace snell {

// `ways[w]` holds every output component of path w, in varying order, and
// `references[w]` the double value along the same path. Adds each
// varying's distinct ways at `sample` when it has more than one.
void addWayAlternatives(std::vector<OracleVarying>& varyings, std::size_t sample,
                        const std::vector<std::vector<Interval>>& ways,
                        const std::vector<std::vector<double>>& references);

}  // namespace snell
