// A capture leaves the context as it found it, so a later draw to a
// framebuffer (images, fragment-stage vectors) is not silently discarded.
#include <gtest/gtest.h>

#include "backends/gl/gl_api.h"
#include "backends/gl/gl_backend.h"
#include "core/errors.h"
#include "gl_test_jobs.h"

namespace snell {
namespace {

const char* const kShader =
    "#version 140\nuniform float s;\nout float y;\n"
    "void main() { y = s; gl_Position = vec4(0.0); }\n";

CaptureJob job() {
  CaptureJob job;
  job.program = gltest::vertexOnly(kShader);
  job.uniforms["s"] = gltest::value(ValueType::Float, {3.0f});
  job.varyings = {"y"};
  job.vertexCount = 4;
  return job;
}

// The backend's core context is the current one after its calls; these
// queries read that context.
void expectRestored() {
  ASSERT_NE(currentGlFunctions, nullptr);
  EXPECT_EQ(glIsEnabled(GL_RASTERIZER_DISCARD), GL_FALSE);
  GLint program = -1;
  glGetIntegerv(GL_CURRENT_PROGRAM, &program);
  EXPECT_EQ(program, 0);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST(GlStateRestore, CaptureLeavesRasterizerDiscardOff) {
  auto backend = makeGlBackend({});
  const CaptureOutcome outcome = backend->captureVertexOutputs(job());
  ASSERT_TRUE(outcome.compile.ok) << outcome.compile.log;
  EXPECT_EQ(outcome.varyings.at(0).data, (std::vector<float>(4, 3.0f)));
  expectRestored();
}

TEST(GlStateRestore, RejectedCaptureLeavesStateAlone) {
  auto backend = makeGlBackend({});
  CaptureJob wrong = job();
  wrong.uniforms["s"] = gltest::value(ValueType::Vec4, {1, 2, 3, 4});
  EXPECT_THROW(backend->captureVertexOutputs(wrong), UsageError);
  expectRestored();
}

TEST(GlStateRestore, AttributeLeftOutReadsTheDefaultNotThePreviousJob) {
  const char* const passThrough =
      "#version 140\nin vec4 a;\nout vec4 y;\n"
      "void main() { y = a; gl_Position = vec4(0.0); }\n";
  auto backend = makeGlBackend({});
  CaptureJob given;
  given.program = gltest::vertexOnly(passThrough);
  gltest::addAttribute(given, gltest::attribute("a", 4, {5, 6, 7, 8, 5, 6, 7, 8}));
  given.varyings = {"y"};
  given.vertexCount = 2;
  ASSERT_EQ(backend->captureVertexOutputs(given).varyings.at(0).data,
            (std::vector<float>{5, 6, 7, 8, 5, 6, 7, 8}));

  CaptureJob leftOut = given;
  leftOut.attributes.clear();
  // GL's generic attribute value when no array is enabled.
  EXPECT_EQ(backend->captureVertexOutputs(leftOut).varyings.at(0).data,
            (std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1}));
}

}  // namespace
}  // namespace snell
