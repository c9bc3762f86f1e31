// The render target is float, its size is the job's, and row 0 of the image
// is the top of clip space.
#include <gtest/gtest.h>

#include "backends/gl/gl_backend.h"
#include "gl_render_test_jobs.h"

namespace snell {
namespace {

using gltest::Rgba;

// None of these is a multiple of 1/255, and two are outside [0, 1]: an
// 8-bit or clamped target cannot return them.
const Rgba kUnquantised = {0.1f, -0.25f, 2.5f, 0.7f};

TEST(GlRenderTarget, ConstantColourReadsBackBitExact) {
  const char* const constant = R"(#version 140
out vec4 FragColor;
void main() { FragColor = vec4(0.1, -0.25, 2.5, 0.7); }
)";
  auto backend = makeGlBackend({});
  gltest::Triangles quad;
  quad.fullScreen(0.5f, {0, 0, 0, 0});
  RenderJob job = gltest::flatColourJob(quad, 5, 3);
  job.program.fragment = constant;
  const RenderOutcome outcome = backend->render(job);
  ASSERT_TRUE(outcome.compile.ok) << outcome.compile.log;
  ASSERT_EQ(outcome.image.width, 5);
  ASSERT_EQ(outcome.image.height, 3);
  ASSERT_EQ(outcome.image.pixels.size(), 5u * 3u * 4u);
  EXPECT_EQ(gltest::pixelsOtherThan(outcome.image, kUnquantised, 0, 0, 5, 3), 0);
  EXPECT_EQ(gltest::pixel(outcome.image, 2, 1), kUnquantised);
}

TEST(GlRenderTarget, AttributeColourAndClearColourReadBackBitExact) {
  auto backend = makeGlBackend({});
  gltest::Triangles quad;
  quad.fullScreen(0.5f, kUnquantised);
  RenderJob job = gltest::flatColourJob(quad, 4, 4);
  const RenderOutcome drawn = backend->render(job);
  ASSERT_TRUE(drawn.compile.ok) << drawn.compile.log;
  EXPECT_EQ(gltest::pixelsOtherThan(drawn.image, kUnquantised, 0, 0, 4, 4), 0);

  const Rgba clear = {0.3f, 1.7f, -0.2f, 0.9f};
  job.indices.clear();
  job.clearColor = clear;
  EXPECT_EQ(gltest::pixelsOtherThan(backend->render(job).image, clear, 0, 0, 4, 4), 0);
}

TEST(GlRenderTarget, TopHalfOfClipSpaceIsTheFirstRows) {
  const Rgba red = {1, 0, 0, 1};
  const int width = 6;
  const int height = 8;
  auto backend = makeGlBackend({});
  gltest::Triangles top;  // covers y in [0, 1] over the whole width
  top.add({-1, 0, 0.5f}, {3, 0, 0.5f}, {-1, 4, 0.5f}, red);
  const RenderOutcome outcome = backend->render(gltest::flatColourJob(top, width, height));
  ASSERT_TRUE(outcome.compile.ok) << outcome.compile.log;
  EXPECT_EQ(gltest::pixelsOtherThan(outcome.image, red, 0, 0, width, height / 2), 0);
  EXPECT_EQ(gltest::pixelsOtherThan(outcome.image, {0, 0, 0, 0}, 0, height / 2, width, height), 0);
}

TEST(GlRenderTarget, LeftHalfOfClipSpaceIsTheFirstColumns) {
  const Rgba green = {0, 1, 0, 1};
  const int width = 8;
  const int height = 6;
  auto backend = makeGlBackend({});
  gltest::Triangles left;  // covers x in [-1, 0] over the whole height
  left.add({-4, -1, 0.5f}, {0, -1, 0.5f}, {0, 3, 0.5f}, green);
  const RenderOutcome outcome = backend->render(gltest::flatColourJob(left, width, height));
  ASSERT_TRUE(outcome.compile.ok) << outcome.compile.log;
  EXPECT_EQ(gltest::pixelsOtherThan(outcome.image, green, 0, 0, width / 2, height), 0);
  EXPECT_EQ(gltest::pixelsOtherThan(outcome.image, {0, 0, 0, 0}, width / 2, 0, width, height), 0);
}

TEST(GlRenderTarget, SizesChangeBetweenRenders) {
  const Rgba blue = {0, 0, 1, 1};
  auto backend = makeGlBackend({});
  gltest::Triangles quad;
  quad.fullScreen(0.5f, blue);
  for (const auto& [width, height] : {std::pair{3, 7}, std::pair{16, 2}, std::pair{3, 7}}) {
    const RenderOutcome outcome = backend->render(gltest::flatColourJob(quad, width, height));
    ASSERT_EQ(outcome.image.width, width);
    ASSERT_EQ(outcome.image.height, height);
    EXPECT_EQ(gltest::pixelsOtherThan(outcome.image, blue, 0, 0, width, height), 0)
        << width << "x" << height;
  }
}

}  // namespace
}  // namespace snell
