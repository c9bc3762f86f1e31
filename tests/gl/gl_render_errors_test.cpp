// A render job that does not fit its program is the user's to fix: a
// UsageError saying what is wrong, never a blank image.
#include <gtest/gtest.h>

#include <string>

#include "backends/gl/gl_backend.h"
#include "core/errors.h"
#include "gl_render_test_jobs.h"

namespace snell {
namespace {

gltest::Triangles quad() {
  gltest::Triangles triangles;
  triangles.fullScreen(0.5f, {1, 1, 1, 1});
  return triangles;
}

void expectUsageErrorMentioning(Backend& backend, const RenderJob& job, const std::string& words) {
  try {
    backend.render(job);
    FAIL() << "expected UsageError mentioning " << words;
  } catch (const UsageError& error) {
    EXPECT_NE(std::string(error.what()).find(words), std::string::npos) << error.what();
  }
}

TEST(GlRenderErrors, OutputAwayFromLocationZeroIsNamed) {
  auto backend = makeGlBackend({});
  RenderJob job = gltest::flatColourJob(quad(), 4, 4);
  job.program.fragment = R"(#version 330
flat in vec4 vColour;
layout(location = 1) out vec4 Shifted;
void main() { Shifted = vColour; }
)";
  expectUsageErrorMentioning(*backend, job, "Shifted at location 1");
}

TEST(GlRenderErrors, VertexOnlyProgramCannotRender) {
  auto backend = makeGlBackend({});
  RenderJob job = gltest::flatColourJob(quad(), 4, 4);
  job.program.fragment.clear();
  expectUsageErrorMentioning(*backend, job, "fragment shader");
}

TEST(GlRenderErrors, IndicesMustMakeWholeTriangles) {
  auto backend = makeGlBackend({});
  RenderJob job = gltest::flatColourJob(quad(), 4, 4);
  job.indices.pop_back();
  expectUsageErrorMentioning(*backend, job, "multiple of 3");
}

TEST(GlRenderErrors, IndexPastTheAttributesIsNamed) {
  auto backend = makeGlBackend({});
  RenderJob job = gltest::flatColourJob(quad(), 4, 4);
  job.indices.back() = 6;  // the quad has vertices 0 to 5
  expectUsageErrorMentioning(*backend, job, "the job draws 7");
}

TEST(GlRenderErrors, EmptySizeIsRejected) {
  auto backend = makeGlBackend({});
  RenderJob job = gltest::flatColourJob(quad(), 0, 4);
  expectUsageErrorMentioning(*backend, job, "0x4");
}

TEST(GlRenderErrors, CompileErrorIsAnOutcomeNotAnException) {
  auto backend = makeGlBackend({});
  RenderJob job = gltest::flatColourJob(quad(), 4, 4);
  job.program.fragment = "#version 140\nout vec4 FragColor;\nvoid main() { FragColor = nope; }\n";
  const RenderOutcome outcome = backend->render(job);
  EXPECT_FALSE(outcome.compile.ok);
  EXPECT_NE(outcome.compile.log.find("fragment shader"), std::string::npos) << outcome.compile.log;
  EXPECT_TRUE(outcome.image.pixels.empty());
}

}  // namespace
}  // namespace snell
