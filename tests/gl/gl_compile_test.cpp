// Bad GLSL is an outcome, not an exception, and its log says which stage of
// which file failed.
#include <gtest/gtest.h>

#include <string>

#include "backends/gl/gl_backend.h"
#include "gl_test_jobs.h"

namespace snell {
namespace {

const char* const kGoodVertex = "#version 140\nin vec4 P;\nvoid main() { gl_Position = P; }\n";
const char* const kGoodFragment = "#version 140\nout vec4 C;\nvoid main() { C = vec4(1.0); }\n";
const char* const kBadVertex = "#version 140\nvoid main() { gl_Position = undeclared; }\n";
const char* const kBadFragment = "#version 140\nout vec4 C;\nvoid main() { C = vec3(1.0) }\n";

ProgramSource program(const char* vertex, const char* fragment) {
  ProgramSource source;
  source.vertex = vertex;
  source.fragment = fragment;
  source.vertexPath = "listings/probe.vert";
  source.fragmentPath = "listings/probe.frag";
  return source;
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(GlCompile, GoodProgramCompiles) {
  auto backend = makeGlBackend({});
  const CompileOutcome outcome = backend->compile(program(kGoodVertex, kGoodFragment));
  EXPECT_TRUE(outcome.ok) << outcome.log;
}

TEST(GlCompile, VertexOnlyProgramCompiles) {
  auto backend = makeGlBackend({});
  EXPECT_TRUE(backend->compile(program(kGoodVertex, "")).ok);
}

TEST(GlCompile, VertexErrorNamesStageAndFile) {
  auto backend = makeGlBackend({});
  const CompileOutcome outcome = backend->compile(program(kBadVertex, kGoodFragment));
  EXPECT_FALSE(outcome.ok);
  EXPECT_TRUE(contains(outcome.log, "vertex shader (listings/probe.vert)")) << outcome.log;
  EXPECT_TRUE(contains(outcome.log, "undeclared")) << outcome.log;
  EXPECT_FALSE(contains(outcome.log, "fragment shader")) << outcome.log;
}

TEST(GlCompile, FragmentErrorNamesStageAndFile) {
  auto backend = makeGlBackend({});
  const CompileOutcome outcome = backend->compile(program(kGoodVertex, kBadFragment));
  EXPECT_FALSE(outcome.ok);
  EXPECT_TRUE(contains(outcome.log, "fragment shader (listings/probe.frag)")) << outcome.log;
  EXPECT_FALSE(contains(outcome.log, "vertex shader")) << outcome.log;
}

TEST(GlCompile, BothStagesAreReportedInOneRun) {
  auto backend = makeGlBackend({});
  const CompileOutcome outcome = backend->compile(program(kBadVertex, kBadFragment));
  EXPECT_FALSE(outcome.ok);
  EXPECT_TRUE(contains(outcome.log, "vertex shader")) << outcome.log;
  EXPECT_TRUE(contains(outcome.log, "fragment shader")) << outcome.log;
}

TEST(GlCompile, CaptureOfBrokenShaderReportsInsteadOfThrowing) {
  auto backend = makeGlBackend({});
  CaptureJob job;
  job.program = gltest::vertexOnly(kBadVertex, Profile::Core, "listings/probe.vert");
  job.varyings = {"Anything"};
  job.vertexCount = 3;
  const CaptureOutcome outcome = backend->captureVertexOutputs(job);
  EXPECT_FALSE(outcome.compile.ok);
  EXPECT_TRUE(contains(outcome.compile.log, "vertex shader (listings/probe.vert)"))
      << outcome.compile.log;
  EXPECT_TRUE(outcome.varyings.empty());
}

TEST(GlCompile, CapturingAnOutputTheShaderLacksIsALinkError) {
  auto backend = makeGlBackend({});
  CaptureJob job;
  job.program = gltest::vertexOnly(kGoodVertex);
  job.varyings = {"Missing"};
  job.vertexCount = 3;
  const CaptureOutcome outcome = backend->captureVertexOutputs(job);
  EXPECT_FALSE(outcome.compile.ok);
  EXPECT_TRUE(contains(outcome.compile.log, "program link")) << outcome.compile.log;
  EXPECT_TRUE(contains(outcome.compile.log, "Missing")) << outcome.compile.log;
  EXPECT_TRUE(outcome.varyings.empty());
}

}  // namespace
}  // namespace snell
