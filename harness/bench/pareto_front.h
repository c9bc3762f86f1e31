#pragma once
// The Pareto front of (cost, error) points: the points no other point beats
// on both at once (no cheaper one that is as accurate, no more accurate one
// that is as cheap).
#include <cstddef>
#include <vector>

namespace snell::bench {

struct CostError {
  double cost = 0;
  double error = 0;
};

// Indices of the points on the front, ordered by cost (then error). Equal
// points are all on it.
std::vector<std::size_t> paretoFront(const std::vector<CostError>& points);

}  // namespace snell::bench
