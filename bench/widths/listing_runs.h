#pragma once
// Runs a catalog listing's hand-written oracle template (Shader<T> in
// harness/oracle/listings) over one of the tool's number types: double for
// the reference value, Deqp for the dEQP-style interval, Sampled for a
// conforming machine's values.
#include <cstddef>
#include <string>
#include <vector>

#include "widths/snell_intervals.h"

namespace snell::widths {

struct ListingInput {
  std::string name;
  int components = 1;
};

// The oracle names with a template here (every registered vertex oracle).
std::vector<std::string> listingOracleNames();

// The listing's per-invocation inputs (vertex attributes or probe values).
std::vector<ListingInput> listingInputs(const std::string& oracle);

// Every output component at `vertex`, in the listing's visit order (the
// order of snellListing's outputs). Throws std::out_of_range for a name
// not in listingOracleNames().
template <class T>
std::vector<T> runListing(const std::string& oracle, const ListingBindings& bindings,
                          std::size_t vertex);

}  // namespace snell::widths
