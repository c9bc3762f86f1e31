// Legacy listings run on a compatibility context made on first use, beside
// the core context, within one backend.
#include <gtest/gtest.h>

#include "backends/gl/gl_backend.h"
#include "gl_test_jobs.h"

namespace snell {
namespace {

// GLSL 1.10 with built-ins that core profiles removed.
const char* const kLegacy = R"(#version 110
attribute vec3 I;
varying vec3 R;
void main() {
  R = reflect(I, vec3(0.0, 0.0, 1.0));
  gl_Position = ftransform();
}
)";

// Mesa accepts GLSL 1.10 with ftransform() on a core context too, so what
// tells the contexts apart is a shader only a compatibility context takes.
const char* const kCompatibilityOnly = R"(#version 150 compatibility
in vec3 I;
out vec3 R;
void main() {
  R = reflect(I, vec3(0.0, 0.0, 1.0));
  gl_Position = ftransform();
}
)";

const char* const kCore = R"(#version 140
in vec3 I;
out vec3 R;
void main() {
  R = reflect(I, vec3(0.0, 0.0, 1.0));
  gl_Position = vec4(0.0);
}
)";

CaptureJob reflectJob(const char* source, Profile profile) {
  CaptureJob job;
  job.program = gltest::vertexOnly(source, profile);
  gltest::addAttribute(job, gltest::attribute("I", 3, {0.6f, 0.0f, -0.8f, 0.0f, 0.5f, 0.25f}));
  job.varyings = {"R"};
  job.vertexCount = 2;
  return job;
}

const std::vector<float> kReflected = {0.6f, 0.0f, 0.8f, 0.0f, 0.5f, -0.25f};

TEST(GlProfile, LegacyListingRunsOnCompatibilityContext) {
  auto backend = makeGlBackend({});
  const CaptureOutcome outcome = backend->captureVertexOutputs(reflectJob(kLegacy, Profile::Compatibility));
  ASSERT_TRUE(outcome.compile.ok) << outcome.compile.log;
  EXPECT_EQ(outcome.varyings.at(0).data, kReflected);
}

TEST(GlProfile, CompatibilityOnlyListingRunsOnlyOnCompatibility) {
  auto backend = makeGlBackend({});
  const CaptureOutcome compatibility =
      backend->captureVertexOutputs(reflectJob(kCompatibilityOnly, Profile::Compatibility));
  ASSERT_TRUE(compatibility.compile.ok) << compatibility.compile.log;
  EXPECT_EQ(compatibility.varyings.at(0).data, kReflected);

  const CaptureOutcome core = backend->captureVertexOutputs(reflectJob(kCompatibilityOnly, Profile::Core));
  EXPECT_FALSE(core.compile.ok);
  EXPECT_NE(core.compile.log.find("vertex shader"), std::string::npos) << core.compile.log;
}

TEST(GlProfile, CoreAndCompatibilityCallsInterleave) {
  auto backend = makeGlBackend({});
  for (int round = 0; round < 3; ++round) {
    const CaptureOutcome legacy =
        backend->captureVertexOutputs(reflectJob(kCompatibilityOnly, Profile::Compatibility));
    const CaptureOutcome core = backend->captureVertexOutputs(reflectJob(kCore, Profile::Core));
    ASSERT_TRUE(legacy.compile.ok) << legacy.compile.log;
    ASSERT_TRUE(core.compile.ok) << core.compile.log;
    EXPECT_EQ(legacy.varyings.at(0).data, kReflected) << "round " << round;
    EXPECT_EQ(core.varyings.at(0).data, kReflected) << "round " << round;
  }
}

TEST(GlProfile, CompileChecksUseTheRequestedProfile) {
  auto backend = makeGlBackend({});
  ProgramSource legacy = gltest::vertexOnly(kCompatibilityOnly, Profile::Compatibility);
  EXPECT_TRUE(backend->compile(legacy).ok);
  legacy.profile = Profile::Core;
  EXPECT_FALSE(backend->compile(legacy).ok);
}

}  // namespace
}  // namespace snell
