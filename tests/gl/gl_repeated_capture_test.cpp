// `snell eval` sends thousands of small jobs with few distinct programs; the
// cache must hand back the right program every time, with fresh inputs.
#include <gtest/gtest.h>

#include <cstddef>
#include <vector>

#include "backends/gl/gl_backend.h"
#include "gl_test_jobs.h"

namespace snell {
namespace {

const char* const kScale =
    "#version 140\nin float x;\nuniform float s;\nout float y;\n"
    "void main() { y = x * s; gl_Position = vec4(0.0); }\n";
const char* const kShift =
    "#version 140\nin float x;\nuniform float s;\nout float y;\n"
    "void main() { y = x + s; gl_Position = vec4(0.0); }\n";

TEST(GlRepeatedCapture, ThousandJobsAlternatingTwoProgramsStayCorrect) {
  auto backend = makeGlBackend({});
  int wrong = 0;
  for (int call = 0; call < 1000; ++call) {
    const bool scale = call % 2 == 0;
    const std::size_t vertices = 1 + static_cast<std::size_t>(call % 37);
    const float s = 0.75f + 0.125f * static_cast<float>(call);
    std::vector<float> x(vertices);
    for (std::size_t v = 0; v < vertices; ++v) x[v] = static_cast<float>(call) - 0.3f * static_cast<float>(v);

    CaptureJob job;
    job.program = gltest::vertexOnly(scale ? kScale : kShift);
    job.uniforms["s"] = gltest::value(ValueType::Float, {s});
    gltest::addAttribute(job, gltest::attribute("x", 1, x));
    job.varyings = {"y"};
    job.vertexCount = vertices;
    const CaptureOutcome outcome = backend->captureVertexOutputs(job);
    ASSERT_TRUE(outcome.compile.ok) << outcome.compile.log;
    const std::vector<float>& y = outcome.varyings.at(0).data;
    ASSERT_EQ(y.size(), vertices) << "call " << call;
    // One correctly rounded fp32 operation: the same on both sides, exactly.
    for (std::size_t v = 0; v < vertices; ++v) {
      const float expected = scale ? x[v] * s : x[v] + s;
      if (y[v] != expected) ++wrong;
    }
  }
  EXPECT_EQ(wrong, 0);
}

TEST(GlRepeatedCapture, TwoBackendsInOneThreadKeepTheirOwnPrograms) {
  auto first = makeGlBackend({});
  auto second = makeGlBackend({});
  for (int call = 0; call < 20; ++call) {
    Backend& backend = call % 2 ? *second : *first;
    CaptureJob job;
    job.program = gltest::vertexOnly(call % 2 ? kShift : kScale);
    job.uniforms["s"] = gltest::value(ValueType::Float, {2.0f});
    gltest::addAttribute(job, gltest::attribute("x", 1, {static_cast<float>(call)}));
    job.varyings = {"y"};
    job.vertexCount = 1;
    const CaptureOutcome outcome = backend.captureVertexOutputs(job);
    ASSERT_TRUE(outcome.compile.ok) << outcome.compile.log;
    const float expected = call % 2 ? static_cast<float>(call) + 2.0f : static_cast<float>(call) * 2.0f;
    EXPECT_EQ(outcome.varyings.at(0).data.at(0), expected) << "call " << call;
  }
}

}  // namespace
}  // namespace snell
