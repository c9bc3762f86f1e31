// End-to-end captures through the public Backend interface, validation on:
// any validation message turns the call that caused it into a SetupError,
// so every passing capture here is also a capture the layer had no words for.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <cstdio>
#include <random>
#include <set>

#include "backends/vk/vk_backend.h"
#include "backends/vk/vk_driver_selection.h"
#include "core/errors.h"
#include "reference_math.h"
#include "vk_test_support.h"

namespace snell {
namespace {

using vktest::Vec3d;

Backend& backend() {
  // One per test process: instance and device creation with the layer costs ~0.1 s.
  static std::unique_ptr<Backend> shared = makeVkBackend(BackendOptions{.validation = true});
  return *shared;
}

const CapturedVarying& varying(const CaptureOutcome& outcome, const std::string& name) {
  for (const CapturedVarying& v : outcome.varyings) {
    if (v.name == name) return v;
  }
  throw std::runtime_error("no captured varying " + name);
}

Value mat(ValueType type, std::vector<float> data) { return Value{type, std::move(data)}; }

TEST(VkBackend, DriverInfoDescribesTheDevice) {
  const DriverInfo info = backend().driverInfo();
  EXPECT_EQ(backend().name(), "vk");
  EXPECT_EQ(info.api, "Vulkan");
  unsigned major = 0, minor = 0, patch = 0;
  char end = 0;
  EXPECT_EQ(std::sscanf(info.apiVersion.c_str(), "%u.%u.%u%c", &major, &minor, &patch, &end), 3)
      << info.apiVersion;
  EXPECT_TRUE(major == 1 && minor >= 1) << info.apiVersion;
  EXPECT_FALSE(info.renderer.empty());
  EXPECT_FALSE(info.driverVersion.empty());
  const std::set<std::string> types = {"cpu", "integrated-gpu", "discrete-gpu", "virtual-gpu",
                                       "other"};
  EXPECT_TRUE(types.count(info.deviceType)) << info.deviceType;
  const char* files = std::getenv("VK_DRIVER_FILES");
  if (files && std::string(files) == vk::kLavapipeManifest) {
    EXPECT_EQ(info.renderer.rfind("llvmpipe", 0), 0u) << info.renderer;
    EXPECT_EQ(info.driverVersion.rfind("llvmpipe Mesa", 0), 0u) << info.driverVersion;
    EXPECT_EQ(info.deviceType, "cpu");
  }
}

TEST(VkBackend, TearDownLeavesNothingForTheValidationLayerToReport) {
  // Messages during destruction have no call to be thrown from, so the
  // backend prints them to stderr; here they must not appear at all.
  ::testing::internal::CaptureStderr();
  {
    auto own = makeVkBackend(BackendOptions{.validation = true});
    CaptureJob job;
    job.program = vktest::vertexProgram(
        "#version 140\nin vec4 P;\nout vec4 Q;\nvoid main() { Q = P * 2.0; gl_Position = P; }\n",
        "probes/q.vert");
    job.varyings = {"Q"};
    job.vertexCount = 3;
    job.attributes["P"] = {"P", 4, std::vector<float>(12, 1.5f)};
    const CaptureOutcome outcome = own->captureVertexOutputs(job);
    EXPECT_TRUE(outcome.compile.ok) << outcome.compile.log;
    EXPECT_EQ(outcome.varyings.empty() ? std::vector<float>{} : outcome.varyings[0].data,
              std::vector<float>(12, 3.0f));
  }
  const std::string stderrText = ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(stderrText.find("Vulkan validation"), std::string::npos) << stderrText;
}

const char* kReflectRefract = R"(#version 140
in vec3 Incident;
in vec3 Normal;
uniform float Eta;
out vec3 Reflected;
out vec3 Refracted;
void main()
{
    Reflected = reflect(Incident, Normal);
    Refracted = refract(Incident, Normal, Eta);
    gl_Position = vec4(0.0);
}
)";

TEST(VkBackendCapture, ReflectAndRefractMatchADoubleReference) {
  // 301 is not a multiple of 3: the padding to whole triangles must not leak out.
  constexpr std::size_t kVertices = 301;
  constexpr float kEta = 1.33f;  // above 1, so some samples take the total-reflection branch
  std::mt19937 random(7);
  std::normal_distribution<double> gauss;
  CaptureJob job;
  job.program = vktest::vertexProgram(kReflectRefract, "probes/reflect_refract.vert");
  job.varyings = {"Reflected", "Refracted"};
  job.vertexCount = kVertices;
  job.uniforms["Eta"] = Value{ValueType::Float, {kEta}};
  AttributeStream& incident = job.attributes["Incident"] = {"Incident", 3, {}};
  AttributeStream& normal = job.attributes["Normal"] = {"Normal", 3, {}};
  for (std::size_t v = 0; v < kVertices; ++v) {
    for (AttributeStream* stream : {&incident, &normal}) {
      const Vec3d unit = vktest::normalizeRef({gauss(random), gauss(random), gauss(random)});
      for (double c : unit) stream->data.push_back(static_cast<float>(c));
    }
  }

  const CaptureOutcome outcome = backend().captureVertexOutputs(job);
  ASSERT_TRUE(outcome.compile.ok) << outcome.compile.log;
  ASSERT_EQ(outcome.varyings.size(), 2u);
  const CapturedVarying& reflected = varying(outcome, "Reflected");
  const CapturedVarying& refracted = varying(outcome, "Refracted");
  ASSERT_EQ(reflected.components, 3);
  ASSERT_EQ(reflected.data.size(), kVertices * 3);
  ASSERT_EQ(refracted.data.size(), kVertices * 3);

  // A plumbing smoke test, not the conformance check (the oracle's spec
  // intervals are that): inputs are unit vectors, so every intermediate is
  // O(1) and each result is under a dozen fp32 operations, each off by at
  // most half an ULP of an O(1) value. 8 * FLT_EPSILON (4 ULPs of 1, 2 ULPs
  // of the largest components, which stay below 4) bounds that, while a
  // wrong offset, order or stride gives O(1) errors. Near k = 0 refract()'s
  // sqrt amplifies rounding without bound, so those few samples are skipped.
  const double tolerance = 8 * FLT_EPSILON;
  int totalReflections = 0, compared = 0;
  for (std::size_t v = 0; v < kVertices; ++v) {
    const Vec3d i = {incident.data[3 * v], incident.data[3 * v + 1], incident.data[3 * v + 2]};
    const Vec3d n = {normal.data[3 * v], normal.data[3 * v + 1], normal.data[3 * v + 2]};
    const Vec3d expectReflect = vktest::reflectRef(i, n);
    const double k = vktest::refractK(i, n, kEta);
    const Vec3d expectRefract = vktest::refractRef(i, n, kEta);
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(reflected.data[3 * v + c], expectReflect[c], tolerance)
          << "vertex " << v << " component " << c;
      if (std::abs(k) < 0.05) continue;
      EXPECT_NEAR(refracted.data[3 * v + c], expectRefract[c], tolerance)
          << "vertex " << v << " component " << c;
    }
    if (std::abs(k) >= 0.05) ++compared;
    if (k < -0.05) ++totalReflections;
  }
  EXPECT_GT(totalReflections, 10) << "the inputs no longer exercise refract()'s k < 0 branch";
  EXPECT_GT(compared, 250);
}

const char* kUniformEcho = R"(#version 140
in float Unused;
uniform mat4 M4;
uniform mat3 M3;
uniform float F;
uniform vec3 V;
out vec4 C0;
out vec4 C1;
out vec4 C2;
out vec4 C3;
out vec3 D0;
out vec3 D1;
out vec3 D2;
out float OutF;
out vec3 OutV;
void main()
{
    C0 = M4[0]; C1 = M4[1]; C2 = M4[2]; C3 = M4[3];
    D0 = M3[0]; D1 = M3[1]; D2 = M3[2];
    OutF = F;
    OutV = V;
    gl_Position = vec4(Unused);
}
)";

TEST(VkBackendCapture, UniformsRoundTripExactly) {
  CaptureJob job;
  job.program = vktest::vertexProgram(kUniformEcho, "probes/uniform_echo.vert");
  job.varyings = {"C0", "C1", "C2", "C3", "D0", "D1", "D2", "OutF", "OutV"};
  job.vertexCount = 2;
  std::vector<float> m4, m3;
  for (int i = 0; i < 16; ++i) m4.push_back(0.5f + static_cast<float>(i) * 1.25f);
  for (int i = 0; i < 9; ++i) m3.push_back(-3.0f + static_cast<float>(i) * 0.375f);
  job.uniforms["M4"] = mat(ValueType::Mat4, m4);
  job.uniforms["M3"] = mat(ValueType::Mat3, m3);
  job.uniforms["F"] = Value{ValueType::Float, {3.14159274f}};
  job.uniforms["V"] = Value{ValueType::Vec3, {1e-3f, -7.5f, 65504.0f}};
  job.uniforms["NotInTheProgram"] = Value{ValueType::Vec2, {9, 9}};

  const CaptureOutcome outcome = backend().captureVertexOutputs(job);
  ASSERT_TRUE(outcome.compile.ok) << outcome.compile.log;
  ASSERT_EQ(outcome.varyings.size(), job.varyings.size());
  for (std::size_t vertex = 0; vertex < job.vertexCount; ++vertex) {
    for (int column = 0; column < 4; ++column) {
      const CapturedVarying& c = varying(outcome, "C" + std::to_string(column));
      for (int row = 0; row < 4; ++row) {
        EXPECT_EQ(c.data[vertex * 4 + row], m4[column * 4 + row])
            << "M4[" << column << "][" << row << "]";
      }
    }
    for (int column = 0; column < 3; ++column) {
      const CapturedVarying& d = varying(outcome, "D" + std::to_string(column));
      for (int row = 0; row < 3; ++row) {
        EXPECT_EQ(d.data[vertex * 3 + row], m3[column * 3 + row])
            << "M3[" << column << "][" << row << "]";
      }
    }
    EXPECT_EQ(varying(outcome, "OutF").data[vertex], 3.14159274f);
    const CapturedVarying& v = varying(outcome, "OutV");
    EXPECT_EQ(v.data[vertex * 3 + 0], 1e-3f);
    EXPECT_EQ(v.data[vertex * 3 + 1], -7.5f);
    EXPECT_EQ(v.data[vertex * 3 + 2], 65504.0f);
  }
}

TEST(VkBackendCapture, UnsetUniformsReadAsZero) {
  CaptureJob job;
  job.program = vktest::vertexProgram(kUniformEcho, "probes/uniform_echo.vert");
  job.varyings = {"OutF", "D1"};
  job.vertexCount = 1;
  job.uniforms["F"] = Value{ValueType::Float, {2.0f}};
  const CaptureOutcome first = backend().captureVertexOutputs(job);
  ASSERT_TRUE(first.compile.ok) << first.compile.log;
  EXPECT_EQ(varying(first, "OutF").data, std::vector<float>{2.0f});
  job.uniforms.clear();  // the previous call's value must not linger in the reused buffer
  const CaptureOutcome second = backend().captureVertexOutputs(job);
  EXPECT_EQ(varying(second, "OutF").data, std::vector<float>{0.0f});
  EXPECT_EQ(varying(second, "D1").data, std::vector<float>(3, 0.0f));
}

TEST(VkBackendCapture, UniformTypeMismatchIsAUsageErrorNamingIt) {
  CaptureJob job;
  job.program = vktest::vertexProgram(kUniformEcho, "probes/uniform_echo.vert");
  job.varyings = {"OutF"};
  job.vertexCount = 3;
  job.uniforms["M3"] = mat(ValueType::Mat4, std::vector<float>(16, 1.0f));
  try {
    backend().captureVertexOutputs(job);
    FAIL() << "a mat4 value for a mat3 uniform was accepted";
  } catch (const UsageError& error) {
    EXPECT_NE(std::string(error.what()).find("'M3'"), std::string::npos) << error.what();
  }
}

TEST(VkBackendCapture, CompileErrorGivesOkFalseAndALogNamingTheFile) {
  const ProgramSource broken = vktest::vertexProgram(
      "#version 140\nout vec3 R;\nvoid main() { R = vec3(1.0) + missing; gl_Position = vec4(0.0); "
      "}\n",
      "probes/broken_capture.vert");
  const CompileOutcome compiled = backend().compile(broken);
  EXPECT_FALSE(compiled.ok);
  EXPECT_NE(compiled.log.find("probes/broken_capture.vert"), std::string::npos) << compiled.log;
  EXPECT_NE(compiled.log.find("missing"), std::string::npos) << compiled.log;

  CaptureJob job;
  job.program = broken;
  job.varyings = {"R"};
  job.vertexCount = 3;
  CaptureOutcome outcome;
  ASSERT_NO_THROW(outcome = backend().captureVertexOutputs(job));
  EXPECT_FALSE(outcome.compile.ok);
  EXPECT_EQ(outcome.compile.log, compiled.log);
  EXPECT_TRUE(outcome.varyings.empty());
}

TEST(VkBackendCapture, CapturingSomethingThatIsNotAnOutputIsAUsageError) {
  CaptureJob job;
  job.program = vktest::vertexProgram(kReflectRefract, "probes/reflect_refract.vert");
  job.varyings = {"Reflected", "Incident"};
  job.vertexCount = 3;
  try {
    backend().captureVertexOutputs(job);
    FAIL() << "capturing an input was accepted";
  } catch (const UsageError& error) {
    EXPECT_NE(std::string(error.what()).find("'Incident' is an input"), std::string::npos)
        << error.what();
  }
}

const char* kAffine = R"(#version 140
in vec3 Position;
in vec4 Extra;
uniform float Scale;
uniform vec3 Offset;
out vec3 Moved;
out vec4 Passed;
void main()
{
    Moved = Position * Scale + Offset;
    Passed = Extra;
    gl_Position = vec4(Position, 1.0);
}
)";

CaptureJob affineJob(std::size_t vertices, float scale, float offset) {
  CaptureJob job;
  job.program = vktest::vertexProgram(kAffine, "probes/affine.vert");
  job.varyings = {"Moved"};
  job.vertexCount = vertices;
  job.uniforms["Scale"] = Value{ValueType::Float, {scale}};
  job.uniforms["Offset"] = Value{ValueType::Vec3, {offset, 2 * offset, -offset}};
  AttributeStream& position = job.attributes["Position"] = {"Position", 3, {}};
  for (std::size_t i = 0; i < vertices * 3; ++i)
    position.data.push_back(static_cast<float>(i % 97));
  return job;
}

// Small integers times small integers plus small integers: exact in fp32.
void expectAffine(const CaptureJob& job, const CaptureOutcome& outcome, float scale, float offset) {
  ASSERT_TRUE(outcome.compile.ok) << outcome.compile.log;
  const CapturedVarying& moved = varying(outcome, "Moved");
  ASSERT_EQ(moved.data.size(), job.vertexCount * 3);
  const float offsets[3] = {offset, 2 * offset, -offset};
  const std::vector<float>& position = job.attributes.at("Position").data;
  for (std::size_t i = 0; i < moved.data.size(); ++i) {
    ASSERT_EQ(moved.data[i], position[i] * scale + offsets[i % 3]) << "float " << i;
  }
}

TEST(VkBackendCapture, AThousandSmallCapturesStayCorrect) {
  for (int call = 0; call < 1000; ++call) {
    const std::size_t vertices = 1 + static_cast<std::size_t>(call % 7);
    const auto scale = static_cast<float>(call % 13);
    const auto offset = static_cast<float>(call);
    const CaptureJob job = affineJob(vertices, scale, offset);
    const CaptureOutcome outcome = backend().captureVertexOutputs(job);
    expectAffine(job, outcome, scale, offset);
    if (::testing::Test::HasFatalFailure()) FAIL() << "call " << call;
  }
}

TEST(VkBackendCapture, BuffersGrowAndShrinkBetweenCalls) {
  for (std::size_t vertices : {3u, 60001u, 4u, 200000u, 1u}) {
    const CaptureJob job = affineJob(vertices, 3.0f, 5.0f);
    expectAffine(job, backend().captureVertexOutputs(job), 3.0f, 5.0f);
  }
}

TEST(VkBackendCapture, MissingAndShortAttributesReadAsOpenGLDefaults) {
  CaptureJob job = affineJob(3, 1.0f, 0.0f);
  job.varyings = {"Passed"};
  // No "Extra" stream: an unset generic attribute reads (0, 0, 0, 1).
  CaptureOutcome outcome = backend().captureVertexOutputs(job);
  ASSERT_TRUE(outcome.compile.ok) << outcome.compile.log;
  EXPECT_EQ(varying(outcome, "Passed").data,
            (std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1}));
  // A 2-component stream for a vec4 input is filled out with (z, w) = (0, 1).
  job.attributes["Extra"] = {"Extra", 2, {5, 6, 7, 8, 9, 10}};
  outcome = backend().captureVertexOutputs(job);
  EXPECT_EQ(varying(outcome, "Passed").data,
            (std::vector<float>{5, 6, 0, 1, 7, 8, 0, 1, 9, 10, 0, 1}));
}

TEST(VkBackendCapture, ShortStreamsAreUsageErrors) {
  CaptureJob job = affineJob(3, 1.0f, 0.0f);
  job.vertexCount = 4;
  EXPECT_THROW(backend().captureVertexOutputs(job), UsageError);
  job.vertexCount = 3;
  job.attributes["Position"].data.pop_back();
  EXPECT_THROW(backend().captureVertexOutputs(job), UsageError);
}

TEST(VkBackendCapture, ZeroVerticesGiveEmptyVaryings) {
  const CaptureJob job = affineJob(0, 1.0f, 0.0f);
  const CaptureOutcome outcome = backend().captureVertexOutputs(job);
  ASSERT_TRUE(outcome.compile.ok) << outcome.compile.log;
  ASSERT_EQ(outcome.varyings.size(), 1u);
  EXPECT_EQ(outcome.varyings[0].name, "Moved");
  EXPECT_EQ(outcome.varyings[0].components, 3);
  EXPECT_TRUE(outcome.varyings[0].data.empty());
}

}  // namespace
}  // namespace snell
