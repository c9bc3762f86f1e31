// Depth test LESS against a depth buffer cleared to 1 on every render, and
// back faces culled only when the job asks.
#include <gtest/gtest.h>

#include "backends/gl/gl_backend.h"
#include "gl_render_test_jobs.h"

namespace snell {
namespace {

using gltest::Rgba;

const Rgba kNear = {0.1f, 0.2f, 0.3f, 1.0f};
const Rgba kFar = {0.7f, 0.6f, 0.5f, 1.0f};
const Rgba kClear = {0, 0, 0, 0};

TEST(GlRenderDepth, NearerWinsWhicheverIsDrawnFirst) {
  auto backend = makeGlBackend({});
  gltest::Triangles nearFirst;
  nearFirst.fullScreen(0.25f, kNear).fullScreen(0.75f, kFar);
  gltest::Triangles farFirst;
  farFirst.fullScreen(0.75f, kFar).fullScreen(0.25f, kNear);
  for (const gltest::Triangles* order : {&nearFirst, &farFirst}) {
    const RenderOutcome outcome = backend->render(gltest::flatColourJob(*order, 4, 4));
    ASSERT_TRUE(outcome.compile.ok) << outcome.compile.log;
    EXPECT_EQ(gltest::pixelsOtherThan(outcome.image, kNear, 0, 0, 4, 4), 0)
        << (order == &nearFirst ? "near drawn first" : "far drawn first");
  }
}

TEST(GlRenderDepth, DepthIsClearedBetweenRenders) {
  auto backend = makeGlBackend({});
  gltest::Triangles nearQuad;
  nearQuad.fullScreen(0.25f, kNear);
  gltest::Triangles farQuad;
  farQuad.fullScreen(0.75f, kFar);
  ASSERT_EQ(gltest::pixelsOtherThan(backend->render(gltest::flatColourJob(nearQuad, 4, 4)).image,
                                    kNear, 0, 0, 4, 4),
            0);
  // With the near quad's depth left behind, this one would fail the test.
  EXPECT_EQ(gltest::pixelsOtherThan(backend->render(gltest::flatColourJob(farQuad, 4, 4)).image,
                                    kFar, 0, 0, 4, 4),
            0);
}

TEST(GlRenderDepth, DepthStartsAtOne) {
  auto backend = makeGlBackend({});
  gltest::Triangles almostFar;  // window depth 0.9995: passes LESS against 1
  almostFar.fullScreen(0.999f, kFar);
  EXPECT_EQ(gltest::pixelsOtherThan(backend->render(gltest::flatColourJob(almostFar, 4, 4)).image,
                                    kFar, 0, 0, 4, 4),
            0);
}

// A triangle covering the whole viewport, wound either way.
gltest::Triangles coveringTriangle(bool clockwise) {
  gltest::Triangles triangle;
  if (clockwise)
    triangle.add({-1, -1, 0.5f}, {-1, 3, 0.5f}, {3, -1, 0.5f}, kNear);
  else
    triangle.add({-1, -1, 0.5f}, {3, -1, 0.5f}, {-1, 3, 0.5f}, kNear);
  return triangle;
}

TEST(GlRenderCull, ClockwiseTriangleIsCulledWhenAsked) {
  auto backend = makeGlBackend({});
  RenderJob job = gltest::flatColourJob(coveringTriangle(true), 4, 4);
  job.cullBackFaces = true;
  EXPECT_EQ(gltest::pixelsOtherThan(backend->render(job).image, kClear, 0, 0, 4, 4), 0);
  job.cullBackFaces = false;
  EXPECT_EQ(gltest::pixelsOtherThan(backend->render(job).image, kNear, 0, 0, 4, 4), 0);
}

TEST(GlRenderCull, CounterClockwiseTriangleIsDrawnWhenCulling) {
  auto backend = makeGlBackend({});
  RenderJob job = gltest::flatColourJob(coveringTriangle(false), 4, 4);
  job.cullBackFaces = true;
  EXPECT_EQ(gltest::pixelsOtherThan(backend->render(job).image, kNear, 0, 0, 4, 4), 0);
}

}  // namespace
}  // namespace snell
