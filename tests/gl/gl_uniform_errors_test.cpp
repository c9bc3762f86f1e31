// A Value that does not fit its uniform is the user's error and says which
// uniform; names and attributes the program lacks are not errors.
#include <gtest/gtest.h>

#include <string>

#include "backends/gl/gl_backend.h"
#include "core/errors.h"
#include "gl_test_jobs.h"

namespace snell {
namespace {

const char* const kShader = R"(#version 140
uniform mat3 NormalMatrix;
uniform float Eta;
in vec3 MCnormal;
out vec3 Normal;
void main() {
  Normal = NormalMatrix * MCnormal * Eta;
  gl_Position = vec4(0.0);
}
)";

CaptureJob job() {
  CaptureJob job;
  job.program = gltest::vertexOnly(kShader);
  job.varyings = {"Normal"};
  job.vertexCount = 1;
  gltest::addAttribute(job, gltest::attribute("MCnormal", 3, {1.0f, 2.0f, 3.0f}));
  job.uniforms["NormalMatrix"] =
      gltest::value(ValueType::Mat3, {1, 0, 0, 0, 1, 0, 0, 0, 1});
  job.uniforms["Eta"] = gltest::value(ValueType::Float, {2.0f});
  return job;
}

std::string usageErrorOf(Backend& backend, const CaptureJob& job) {
  try {
    backend.captureVertexOutputs(job);
  } catch (const UsageError& error) {
    return error.what();
  }
  return "";
}

TEST(GlUniformErrors, MatchingJobRuns) {
  auto backend = makeGlBackend({});
  const CaptureOutcome outcome = backend->captureVertexOutputs(job());
  ASSERT_TRUE(outcome.compile.ok) << outcome.compile.log;
  EXPECT_EQ(outcome.varyings.at(0).data, (std::vector<float>{2.0f, 4.0f, 6.0f}));
}

TEST(GlUniformErrors, WrongTypeThrowsUsageErrorNamingTheUniform) {
  auto backend = makeGlBackend({});
  CaptureJob wrong = job();
  wrong.uniforms["NormalMatrix"] = gltest::value(ValueType::Mat4, std::vector<float>(16, 0.0f));
  const std::string message = usageErrorOf(*backend, wrong);
  EXPECT_NE(message.find("'NormalMatrix'"), std::string::npos) << message;
  EXPECT_NE(message.find("mat3"), std::string::npos) << message;
  EXPECT_NE(message.find("mat4"), std::string::npos) << message;
}

TEST(GlUniformErrors, VectorForAFloatThrowsUsageError) {
  auto backend = makeGlBackend({});
  CaptureJob wrong = job();
  wrong.uniforms["Eta"] = gltest::value(ValueType::Vec3, {0.66f, 0.67f, 0.68f});
  EXPECT_NE(usageErrorOf(*backend, wrong).find("'Eta'"), std::string::npos);
}

TEST(GlUniformErrors, WrongFloatCountThrowsUsageError) {
  auto backend = makeGlBackend({});
  CaptureJob wrong = job();
  wrong.uniforms["Eta"] = gltest::value(ValueType::Float, {0.66f, 0.67f});
  EXPECT_NE(usageErrorOf(*backend, wrong).find("'Eta'"), std::string::npos);
}

TEST(GlUniformErrors, RejectedJobDoesNotSpoilTheNext) {
  auto backend = makeGlBackend({});
  CaptureJob wrong = job();
  wrong.uniforms["Eta"] = gltest::value(ValueType::Vec2, {5.0f, 5.0f});
  wrong.uniforms["NormalMatrix"] = gltest::value(ValueType::Mat3, std::vector<float>(9, 7.0f));
  EXPECT_THROW(backend->captureVertexOutputs(wrong), UsageError);
  const CaptureOutcome outcome = backend->captureVertexOutputs(job());
  EXPECT_EQ(outcome.varyings.at(0).data, (std::vector<float>{2.0f, 4.0f, 6.0f}));
}

TEST(GlUniformErrors, NamesTheProgramLacksAreIgnored) {
  auto backend = makeGlBackend({});
  CaptureJob extra = job();
  extra.uniforms["MVPMatrix"] = gltest::value(ValueType::Mat4, std::vector<float>(16, 1.0f));
  gltest::addAttribute(extra, gltest::attribute("MCvertex", 4, {9, 9, 9, 9}));
  const CaptureOutcome outcome = backend->captureVertexOutputs(extra);
  ASSERT_TRUE(outcome.compile.ok) << outcome.compile.log;
  EXPECT_EQ(outcome.varyings.at(0).data, (std::vector<float>{2.0f, 4.0f, 6.0f}));
}

TEST(GlUniformErrors, AttributeShorterThanTheJobThrowsUsageError) {
  auto backend = makeGlBackend({});
  CaptureJob wrong = job();
  wrong.vertexCount = 2;
  EXPECT_THROW(backend->captureVertexOutputs(wrong), UsageError);
}

}  // namespace
}  // namespace snell
