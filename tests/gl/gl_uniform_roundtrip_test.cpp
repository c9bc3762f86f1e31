// Uniforms set from Values reach the shader bit for bit, matrices in
// column-major order, and a cached program does not keep a previous job's
// uniforms.
#include <gtest/gtest.h>

#include <vector>

#include "backends/gl/gl_backend.h"
#include "gl_test_jobs.h"

namespace snell {
namespace {

const char* const kCopyShader = R"(#version 140
uniform mat4 M;
uniform mat3 R;
uniform float f;
uniform vec3 v;
uniform float g = 2.5;
out mat4 OutM;
out mat3 OutR;
out float OutF;
out vec3 OutV;
out float OutG;
void main() {
  OutM = M;
  OutR = R;
  OutF = f;
  OutV = v;
  OutG = g;
  gl_Position = vec4(0.0);
}
)";

// No symmetric entries, so a transposed upload shows; values that are not
// short binary fractions, so a float-to-half or double path would show.
const std::vector<float> kMat4 = {0.1f, -1.7f, 3.3f,  4e-3f, 5.5f,  -6.25f, 7.1f,  8e5f,
                                  9.9f, 10.3f, -11.f, 12.7f, 1e-7f, 14.2f,  -15.f, 16.6f};
const std::vector<float> kMat3 = {1.1f, 2.2f, -3.3f, 4.4f, 5.5f, 6.6f, -7.7f, 8.8f, 9.9f};
const std::vector<float> kVec3 = {0.333333f, -2.71828f, 3.14159f};
constexpr float kFloat = -0.6666667f;
constexpr std::size_t kVertices = 5;

CaptureJob copyJob() {
  CaptureJob job;
  job.program = gltest::vertexOnly(kCopyShader);
  job.varyings = {"OutM", "OutR", "OutF", "OutV", "OutG"};
  job.vertexCount = kVertices;
  return job;
}

void expectEveryVertexEquals(const CaptureOutcome& outcome, const std::string& name,
                             const std::vector<float>& expected) {
  const CapturedVarying& captured = gltest::varyingNamed(outcome, name);
  ASSERT_EQ(captured.components, static_cast<int>(expected.size())) << name;
  ASSERT_EQ(captured.data.size(), kVertices * expected.size()) << name;
  for (std::size_t vertex = 0; vertex < kVertices; ++vertex)
    for (std::size_t c = 0; c < expected.size(); ++c)
      EXPECT_EQ(captured.data[vertex * expected.size() + c], expected[c])
          << name << " vertex " << vertex << " component " << c;
}

TEST(GlUniformRoundTrip, ValuesComeBackExactly) {
  CaptureJob job = copyJob();
  job.uniforms["M"] = gltest::value(ValueType::Mat4, kMat4);
  job.uniforms["R"] = gltest::value(ValueType::Mat3, kMat3);
  job.uniforms["f"] = gltest::value(ValueType::Float, {kFloat});
  job.uniforms["v"] = gltest::value(ValueType::Vec3, kVec3);
  job.uniforms["g"] = gltest::value(ValueType::Float, {-4.0f});

  auto backend = makeGlBackend({});
  const CaptureOutcome outcome = backend->captureVertexOutputs(job);
  ASSERT_TRUE(outcome.compile.ok) << outcome.compile.log;
  expectEveryVertexEquals(outcome, "OutM", kMat4);
  expectEveryVertexEquals(outcome, "OutR", kMat3);
  expectEveryVertexEquals(outcome, "OutF", {kFloat});
  expectEveryVertexEquals(outcome, "OutV", kVec3);
  expectEveryVertexEquals(outcome, "OutG", {-4.0f});
}

TEST(GlUniformRoundTrip, UniformsLeftOutGetTheirLinkTimeValuesBack) {
  auto backend = makeGlBackend({});
  CaptureJob first = copyJob();
  first.uniforms["f"] = gltest::value(ValueType::Float, {kFloat});
  first.uniforms["g"] = gltest::value(ValueType::Float, {-4.0f});
  first.uniforms["v"] = gltest::value(ValueType::Vec3, kVec3);
  ASSERT_TRUE(backend->captureVertexOutputs(first).compile.ok);

  CaptureJob second = copyJob();
  second.uniforms["v"] = gltest::value(ValueType::Vec3, {1.0f, 2.0f, 3.0f});
  const CaptureOutcome outcome = backend->captureVertexOutputs(second);
  ASSERT_TRUE(outcome.compile.ok) << outcome.compile.log;
  expectEveryVertexEquals(outcome, "OutF", {0.0f});  // uniforms start at zero
  expectEveryVertexEquals(outcome, "OutG", {2.5f});  // the declaration's initializer
  expectEveryVertexEquals(outcome, "OutV", {1.0f, 2.0f, 3.0f});
}

}  // namespace
}  // namespace snell
