// How the sweep's charts form their series where several would draw the
// same marks or lines.
#include "sweep/chart_series.h"

#include <gtest/gtest.h>

namespace snell::sweep {
namespace {

// Three backends breaking the same way at a point are one mark, titled by
// all three; where one of them does not break, the others' mark is theirs
// alone, and a different kind at the same point is its own series.
TEST(ChartSeries, BackendsThatAgreeShareOneMark) {
  const std::vector<MapMark> marks = {
      {"gl", "zero_vector_direction (undefined)", 45, 1.5},
      {"oracle", "zero_vector_direction (undefined)", 45, 1.5},
      {"vk", "zero_vector_direction (undefined)", 45, 1.5},
      {"gl", "zero_vector_direction (undefined)", 46, 1.5},
      {"vk", "zero_vector_direction (undefined)", 46, 1.5},
      {"vk", "outside_spec (implementation)", 46, 1.5},
  };
  const std::map<std::string, std::string> series = mergedMarks(marks);
  ASSERT_EQ(series.size(), 3u);
  EXPECT_EQ(series.at("gl, oracle, vk: zero_vector_direction (undefined)"), "45 1.5\n");
  EXPECT_EQ(series.at("gl, vk: zero_vector_direction (undefined)"), "46 1.5\n");
  EXPECT_EQ(series.at("vk: outside_spec (implementation)"), "46 1.5\n");
}

TEST(ChartSeries, OneBackendAloneKeepsItsOwnSeries) {
  const std::map<std::string, std::string> series =
      mergedMarks({{"gl", "crash (implementation)", 1, 2}, {"gl", "crash (implementation)", 3, 4}});
  ASSERT_EQ(series.size(), 1u);
  EXPECT_EQ(series.at("gl: crash (implementation)"), "1 2\n3 4\n");
}

TEST(ChartSeries, ACurveOnAnEarlierOneIsNamed) {
  const auto same = sameAsEarlier({"0 1\n", "0 2\n", "0 1\n", "", ""});
  ASSERT_EQ(same.size(), 5u);
  EXPECT_FALSE(same[0]);
  EXPECT_FALSE(same[1]);
  ASSERT_TRUE(same[2]);
  EXPECT_EQ(*same[2], 0u);
  // Empty curves draw nothing: neither lies on the other.
  EXPECT_FALSE(same[3]);
  EXPECT_FALSE(same[4]);
}

}  // namespace
}  // namespace snell::sweep
