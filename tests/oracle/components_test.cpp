#include "oracle/components.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

namespace snell {
namespace {

TEST(Components, HoldsUpToFourAndRefusesAFifth) {
  Components<double> c{1.0, 2.0, 3.0};
  EXPECT_EQ(c.size(), 3u);
  c.push_back(4.0);
  EXPECT_EQ(std::vector<double>(c), (std::vector<double>{1.0, 2.0, 3.0, 4.0}));
  EXPECT_THROW(c.push_back(5.0), std::length_error);
  EXPECT_THROW((Components<float>{1, 2, 3, 4, 5}), std::length_error);
}

TEST(Components, EqualityLooksAtTheSizeAndEveryComponent) {
  EXPECT_EQ((Components<bool>{true, false}), (Components<bool>{true, false}));
  EXPECT_FALSE((Components<bool>{true, false}) == (Components<bool>{true, true}));
  EXPECT_FALSE((Components<float>{1.0f}) == (Components<float>{1.0f, 0.0f}));
  Components<float> reassigned{9.0f, 9.0f, 9.0f};
  const std::vector<float> two{1.0f, 2.0f};
  reassigned.assign(two.begin(), two.end());
  EXPECT_EQ(reassigned, (Components<float>{1.0f, 2.0f}));
  EXPECT_TRUE(Components<double>().empty());
}

}  // namespace
}  // namespace snell
