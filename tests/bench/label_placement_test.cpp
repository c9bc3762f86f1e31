// Chart labels: methods at nearly the same place (two that draw the same
// picture at the same cost) get labels that do not print on each other.
#include "bench/label_placement.h"

#include <gtest/gtest.h>

#include "bench/bench_chart.h"

namespace snell::bench {
namespace {

bool anyOverlap(const std::vector<LabelledPoint>& points, const std::vector<LabelOffset>& offsets) {
  for (std::size_t i = 0; i < points.size(); ++i)
    for (std::size_t j = i + 1; j < points.size(); ++j)
      if (overlaps(labelBox(points[i], offsets[i], 0.8), labelBox(points[j], offsets[j], 0.8)))
        return true;
  return false;
}

// The Fresnel ladder on vk: three methods within a few hundredths of a
// millisecond and a few per cent of error of each other.
const std::vector<LabelledPoint> kCrowded{{40.0, 10.0, "3-schlick-vertex"},
                                          {40.3, 10.1, "4-schlick-fragment"},
                                          {40.1, 10.1, "5-schlick-dense-side"},
                                          {40.2, 10.05, "2-empirical"}};

TEST(LabelPlacement, OneOffsetForEveryPointShowsTheCheck) {
  // The one fixed offset every label had: the boxes overlap, which is what
  // the check below must see.
  const std::vector<LabelOffset> fixed(kCrowded.size(), LabelOffset{0.8, 0.6});
  EXPECT_TRUE(anyOverlap(kCrowded, fixed));
}

TEST(LabelPlacement, CrowdedPointsGetLabelsThatDoNotOverlap) {
  const std::vector<LabelOffset> offsets = placeLabels(kCrowded, 0.8);
  ASSERT_EQ(offsets.size(), kCrowded.size());
  EXPECT_FALSE(anyOverlap(kCrowded, offsets));
}

TEST(LabelPlacement, CoincidentPointsGetDistinctPlaces) {
  const std::vector<LabelledPoint> same{
      {50, 12, "a-method"}, {50, 12, "b-method"}, {50, 12, "c-method"}, {50, 12, "d-method"}};
  const std::vector<LabelOffset> offsets = placeLabels(same, 0.8);
  EXPECT_FALSE(anyOverlap(same, offsets));
}

TEST(LabelPlacement, APointAloneKeepsTheNearestPlace) {
  const std::vector<LabelOffset> offsets = placeLabels({{10, 10, "alone"}}, 0.8);
  ASSERT_EQ(offsets.size(), 1u);
  EXPECT_DOUBLE_EQ(offsets[0].dx, 0.8);
  EXPECT_DOUBLE_EQ(offsets[0].dy, 0.6);
}

TEST(LabelPlacement, ChartSpaceIsLinearInTimeAndLogarithmicInError) {
  EXPECT_DOUBLE_EQ(labelColumn(5, 0, 10), 50.0);
  EXPECT_NEAR(labelLine(1.0, 0.01, 100.0), 27.5 / 2, 1e-9);
  EXPECT_NEAR(labelLine(0.1, 0.01, 100.0), 27.5 / 4, 1e-9);
}

}  // namespace
}  // namespace snell::bench
