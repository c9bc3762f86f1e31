#include "bench/pareto_front.h"

#include <algorithm>

namespace snell::bench {

std::vector<std::size_t> paretoFront(const std::vector<CostError>& points) {
  auto dominates = [](const CostError& a, const CostError& b) {
    return a.cost <= b.cost && a.error <= b.error && (a.cost < b.cost || a.error < b.error);
  };
  std::vector<std::size_t> front;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const bool beaten = std::any_of(points.begin(), points.end(), [&](const CostError& other) {
      return dominates(other, points[i]);
    });
    if (!beaten) front.push_back(i);
  }
  std::sort(front.begin(), front.end(), [&](std::size_t a, std::size_t b) {
    if (points[a].cost != points[b].cost) return points[a].cost < points[b].cost;
    return points[a].error < points[b].error;
  });
  return front;
}

}  // namespace snell::bench
