// Captures and renders share a context's programs and vertex inputs; each
// puts back what the other relies on, so they interleave in any order.
#include <gtest/gtest.h>

#include "backends/gl/gl_api.h"
#include "backends/gl/gl_backend.h"
#include "core/errors.h"
#include "gl_render_test_jobs.h"

namespace snell {
namespace {

const char* const kReflect = R"(#version 140
in vec3 I;
out vec3 R;
void main() {
  R = reflect(I, vec3(0.0, 0.0, 1.0));
  gl_Position = vec4(0.0);
}
)";

CaptureJob reflectJob() {
  CaptureJob job;
  job.program = gltest::vertexOnly(kReflect);
  gltest::addAttribute(job, gltest::attribute("I", 3, {0.6f, 0.0f, -0.8f, 0.0f, 0.5f, 0.25f}));
  job.varyings = {"R"};
  job.vertexCount = 2;
  return job;
}

// The backend's context is current after its calls; these read it.
void expectCaptureStateIntact() {
  ASSERT_NE(currentGlFunctions, nullptr);
  EXPECT_EQ(glIsEnabled(GL_RASTERIZER_DISCARD), GL_FALSE);
  EXPECT_EQ(glIsEnabled(GL_DEPTH_TEST), GL_FALSE);
  EXPECT_EQ(glIsEnabled(GL_CULL_FACE), GL_FALSE);
  GLint bound = -1;
  glGetIntegerv(GL_CURRENT_PROGRAM, &bound);
  EXPECT_EQ(bound, 0);
  glGetIntegerv(GL_FRAMEBUFFER_BINDING, &bound);
  EXPECT_EQ(bound, 0);
  glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &bound);
  EXPECT_EQ(bound, 0);
  glGetIntegerv(GL_TEXTURE_BINDING_CUBE_MAP, &bound);
  EXPECT_EQ(bound, 0);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST(GlRenderInterleave, TwentyCaptureRenderPairsGiveIdenticalResults) {
  auto backend = makeGlBackend({});
  const CubeMap map = gltest::distinctTexelCubeMap(4, CubeFilter::Linear);
  const RenderJob render = gltest::lookupJob(map, {-0.5f, 0.5f, 1});
  const CaptureJob capture = reflectJob();

  const CaptureOutcome firstCapture = backend->captureVertexOutputs(capture);
  ASSERT_TRUE(firstCapture.compile.ok) << firstCapture.compile.log;
  const RenderOutcome firstRender = backend->render(render);
  ASSERT_TRUE(firstRender.compile.ok) << firstRender.compile.log;
  ASSERT_EQ(firstCapture.varyings.at(0).data,
            (std::vector<float>{0.6f, 0.0f, 0.8f, 0.0f, 0.5f, -0.25f}));
  ASSERT_NE(gltest::pixel(firstRender.image, 0, 0), (gltest::Rgba{0, 0, 0, 0}));

  for (int round = 0; round < 20; ++round) {
    // Odd rounds render first, so calls of each kind follow both kinds.
    const bool renderFirst = round % 2 != 0;
    if (renderFirst) {
      EXPECT_EQ(backend->render(render).image.pixels, firstRender.image.pixels)
          << "round " << round;
    }
    EXPECT_EQ(backend->captureVertexOutputs(capture).varyings.at(0).data,
              firstCapture.varyings.at(0).data)
        << "round " << round;
    if (!renderFirst) {
      EXPECT_EQ(backend->render(render).image.pixels, firstRender.image.pixels)
          << "round " << round;
    }
    expectCaptureStateIntact();
  }
}

TEST(GlRenderInterleave, RenderLeavesCaptureStateIntact) {
  auto backend = makeGlBackend({});
  const CubeMap map = gltest::distinctTexelCubeMap(2, CubeFilter::Nearest);
  ASSERT_TRUE(backend->render(gltest::lookupJob(map, {0, 0, 1})).compile.ok);
  expectCaptureStateIntact();
}

TEST(GlRenderInterleave, RejectedRenderLeavesCaptureStateIntact) {
  auto backend = makeGlBackend({});
  const CubeMap map = gltest::distinctTexelCubeMap(2, CubeFilter::Nearest);
  RenderJob wrong = gltest::lookupJob(map, {0, 0, 1});
  // Found wrong only once the program is bound.
  wrong.uniforms["dir"] = gltest::value(ValueType::Vec4, {0, 0, 1, 0});
  EXPECT_THROW(backend->render(wrong), UsageError);
  expectCaptureStateIntact();
  EXPECT_EQ(backend->captureVertexOutputs(reflectJob()).varyings.at(0).data,
            (std::vector<float>{0.6f, 0.0f, 0.8f, 0.0f, 0.5f, -0.25f}));
}

}  // namespace
}  // namespace snell
