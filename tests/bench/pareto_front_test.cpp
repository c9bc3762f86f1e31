#include "bench/pareto_front.h"

#include <gtest/gtest.h>

namespace snell::bench {
namespace {

TEST(ParetoFront, KeepsOnlyPointsNothingBeatsOnBoth) {
  // cost, error: 0 cheap and bad; 1 dominated by 2 (slower and worse);
  // 2 and 3 trade; 4 dominated by 3; 5 slowest and best.
  const std::vector<CostError> points{{1.0, 10.0}, {3.0, 6.0}, {2.0, 5.0},
                                      {4.0, 2.0},  {4.5, 3.0}, {8.0, 0.5}};
  EXPECT_EQ(paretoFront(points), (std::vector<std::size_t>{0, 2, 3, 5}));
}

TEST(ParetoFront, EqualPointsAreBothOnItAndAnEqualCostNeedsLessError) {
  const std::vector<CostError> points{{1.0, 1.0}, {1.0, 1.0}, {1.0, 2.0}};
  EXPECT_EQ(paretoFront(points), (std::vector<std::size_t>{0, 1}));
  EXPECT_TRUE(paretoFront({}).empty());
}

}  // namespace
}  // namespace snell::bench
