#pragma once
// One sample of a derived program whose branches may go either way, run
// again once per way (oracle/branch_paths.h): each way is a consistent
// value for every output, kept apart as an alternative, and the sample's
// allowed range becomes the hull of the ways, as ListingOracle does for the
// hand-written oracles.
#include <cstddef>
#include <vector>

#include "core/expected_values.h"
#include "core/values.h"
#include "derived/ir.h"

namespace snell::derived {

// Replaces `sample`'s lo/hi (and undefined flags from the intervals) in
// `varyings` by the hull of its ways and adds the ways as alternatives.
void keepWaysApart(const Program& program, const UniformMap& uniforms, const AttributeMap& inputs,
                   std::size_t sample, std::vector<OracleVarying>& varyings);

}  // namespace snell::derived
