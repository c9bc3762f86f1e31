#include "bench/image_error.h"

#include <gtest/gtest.h>

#include <cmath>

namespace snell::bench {
namespace {

Image filled(float value, int size = 4) {
  Image image(size, size);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      float* p = image.at(x, y);
      p[0] = p[1] = p[2] = value;
      p[3] = 1.0f;
    }
  return image;
}

TEST(ImageError, IsZeroForTheSameImageAndCountsOneChangedPixel) {
  const Image reference = filled(0.5f);
  const std::vector<bool> covers(16, true);
  const ImageError same = imageError(reference, reference, covers);
  EXPECT_EQ(same.compared, 16u);
  EXPECT_EQ(same.rms, 0.0);
  EXPECT_EQ(same.deMean, 0.0);

  Image changed = reference;
  changed.at(1, 2)[0] = 0.9f;  // one channel of one pixel off by 0.4
  const ImageError off = imageError(changed, reference, covers);
  EXPECT_NEAR(off.max, 0.4, 1e-6);
  EXPECT_NEAR(off.rms, std::sqrt(0.16 / 48.0), 1e-6);
  EXPECT_GT(off.deMean, 0.0);
  // The 95th percentile's nearest rank is ceil(0.95 * 16) = 16: the changed pixel.
  EXPECT_NEAR(off.deP95, 16.0 * off.deMean, 1e-9);
}

TEST(ImageError, ComparesOnlyWhereBothCoverAndCountsTheRest) {
  const Image reference = filled(0.5f);
  Image rendered = filled(0.2f);
  rendered.at(0, 0)[3] = 0.0f;  // not drawn
  std::vector<bool> covers(16, true);
  covers[15] = false;  // the reference misses the last pixel
  const ImageError error = imageError(rendered, reference, covers);
  EXPECT_EQ(error.compared, 14u);
  EXPECT_EQ(error.coverageMismatch, 2u);
  EXPECT_NEAR(error.rms, 0.3, 1e-6);
}

TEST(Percentile, IsTheNearestRank) {
  EXPECT_EQ(percentile({5, 1, 3, 2, 4}, 50.0), 3.0);
  EXPECT_EQ(percentile({5, 1, 3, 2, 4}, 100.0), 5.0);
  EXPECT_EQ(percentile({5, 1, 3, 2, 4}, 1.0), 1.0);
  EXPECT_EQ(percentile({}, 95.0), 0.0);
}

}  // namespace
TEST(Median, OfAnEvenCountIsTheMeanOfTheMiddleTwo) {
  EXPECT_EQ(median({4.0, 1.0}), 2.5);  // --repeats 2 gave the minimum, 1
  EXPECT_EQ(median({3.0, 1.0, 2.0}), 2.0);
  EXPECT_EQ(median({1.0, 2.0, 10.0, 3.0}), 2.5);
  EXPECT_EQ(median({}), 0.0);
  EXPECT_EQ(percentile({4.0, 1.0}, 50.0), 1.0);  // the nearest rank, unchanged
}

}  // namespace snell::bench
