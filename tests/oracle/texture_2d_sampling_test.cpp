// The CPU reference's 2D sampling (LINEAR, REPEAT, base level) against
// values worked out from the spec's formulas by hand, and against the one
// closed form bilinear filtering must reproduce: a texture that is linear
// in (i, j) is returned exactly, anywhere its footprint does not wrap.
#include "oracle/reference/texture_2d_sampling.h"

#include <gtest/gtest.h>

#include <random>

#include "oracle/glsl/texture.h"

namespace snell {
namespace {

Image rampImage(int width, int height) {
  Image image(width, height);
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i) {
      float* texel = image.at(i, j);
      texel[0] = static_cast<float>(i);
      texel[1] = static_cast<float>(j);
      texel[2] = static_cast<float>(i + 10 * j);
      texel[3] = 1.0f;
    }
  return image;
}

TEST(Texture2DSampling, TexelCentresReturnTheTexelRowJIsTJ) {
  const Image image = rampImage(4, 3);
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 4; ++i) {
      const Rgba value = sampleTexture2D(image, (i + 0.5) / 4, (j + 0.5) / 3);
      EXPECT_EQ(value[0], i);
      EXPECT_EQ(value[1], j);
      EXPECT_EQ(value[3], 1.0);
    }
}

TEST(Texture2DSampling, InsideTheTextureALinearRampIsReproducedExactly) {
  const Image image = rampImage(8, 8);
  std::mt19937 random(7);
  // Footprints that stay inside: texel-space u in [0, 7], i.e. s in [0.5/8, 7.5/8].
  std::uniform_real_distribution<double> inside(0.5 / 8, 7.5 / 8);
  for (int k = 0; k < 1000; ++k) {
    const double s = inside(random), t = inside(random);
    const Rgba value = sampleTexture2D(image, s, t);
    EXPECT_NEAR(value[0], s * 8 - 0.5, 1e-12);
    EXPECT_NEAR(value[1], t * 8 - 0.5, 1e-12);
    EXPECT_NEAR(value[2], (s * 8 - 0.5) + 10 * (t * 8 - 0.5), 1e-11);
  }
}

TEST(Texture2DSampling, RepeatMixesTheLastColumnAndRowWithTheFirst) {
  const Image image = rampImage(4, 2);
  // s = 0: u = -1/2, so i0 = -1 mod 4 = 3 and i1 = 0, weights 1/2 each.
  EXPECT_DOUBLE_EQ(sampleTexture2D(image, 0.0, 0.25)[0], 1.5);
  // s = 1/32: u = -3/8, alpha = 5/8: 3 * 3/8 + 0 * 5/8.
  EXPECT_DOUBLE_EQ(sampleTexture2D(image, 1.0 / 32, 0.25)[0], 9.0 / 8);
  // t = 1: v = 3/2, rows 1 and 2 mod 2 = 0.
  EXPECT_DOUBLE_EQ(sampleTexture2D(image, 0.375, 1.0)[1], 0.5);
}

TEST(Texture2DSampling, CoordinatesOutsideZeroOneLandWhereTheirFractionDoes) {
  const Image image = rampImage(4, 2);
  for (double shift : {-3.0, -1.0, 1.0, 2.0, 17.0}) {
    const Rgba inside = sampleTexture2D(image, 0.3, 0.6);
    const Rgba shifted = sampleTexture2D(image, 0.3 + shift, 0.6 - shift);
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(shifted[c], inside[c], 1e-12) << shift;
  }
}

TEST(Texture2DSampling, GlslTextureMarksANonFiniteCoordinateUndefined) {
  const Image image = rampImage(4, 2);
  glsl::sampler2D sampler{&image};
  const glsl::vec4<double> value = texture(sampler, glsl::vec2<double>(0.375, 0.25));
  EXPECT_EQ(value[0], 1.0);
  EXPECT_FALSE(sampler.undefinedLookup);
  const glsl::vec4<double> nan = texture(sampler, glsl::vec2<double>(std::nan(""), 0.25));
  EXPECT_EQ(nan[0], 0.0);
  EXPECT_TRUE(sampler.undefinedLookup);
}

}  // namespace
}  // namespace snell
