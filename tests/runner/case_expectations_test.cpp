// What a case's manifest says it expects, held to on both backends: fragment
// values checked from probes (and failed when a probe's line never ran),
// listings that must not compile, and backends a listing cannot run on.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "backends/backend.h"
#include "core/errors.h"
#include "core/case.h"
#include "runner/case_runner.h"

namespace snell {
namespace {

namespace fs = std::filesystem;

const char* kVertex = R"(#version 140
uniform mat4 modelViewMatrix;
uniform mat4 modelViewProjectionMatrix;
uniform mat3 normalMatrix;
in vec4 vertex;
in vec3 normal;
out vec3 myvert;
out vec3 mynorm;
void main()
{
    myvert = vec3(modelViewMatrix * vertex);
    mynorm = normalize(normalMatrix * normal);
    gl_Position = modelViewProjectionMatrix * vertex;
}
)";

// CS 381's refraction fragment in core GLSL, with a branch that never runs
// (lines 11 to 13) for a probe that is never written.
const char* kFragment = R"(#version 140
uniform samplerCube mycube0;
in vec3 myvert;
in vec3 mynorm;
out vec4 FragColor;
void main()
{
    float index = 1.1;
    vec3 viewdir = normalize(myvert);
    vec3 refractview = refract(viewdir, mynorm, 1./index);
    if (index > 5.0) {
        refractview = refractview;
    }
    FragColor = texture(mycube0, refractview);
}
)";

const char* kManifestHead = R"(id      = "test/refraction"
title   = "refraction probe test"
source  = { file = "001_e91fe8c1a97f5296.txt", where = "first GLSL fragment" }
stages  = { vertex = "r.vert", fragment = "r.frag" }
oracle  = "cs381_refraction"
constants = { index = 1.1 }
)";

const char* kManifestBody = R"(
[inputs]
vertex = "scene.position"
normal = "scene.normal"

[uniforms]
modelViewMatrix           = "scene.modelview"
modelViewProjectionMatrix = "scene.modelview_projection"
normalMatrix              = "scene.normal_matrix"
mycube0                   = "scene.environment"

[[case]]
scene = "sphere"
)";

std::string captures(int refractviewLine) {
  return "[capture]\nfragment = [\n"
         "  { name = \"myvert\", type = \"vec3\", line = 8 },\n"
         "  { name = \"mynorm\", type = \"vec3\", line = 8 },\n"
         "  { name = \"viewdir\", type = \"vec3\", line = 9 },\n"
         "  { name = \"refractview\", type = \"vec3\", line = " +
         std::to_string(refractviewLine) + " },\n]\n";
}

class CaseExpectations : public testing::TestWithParam<const char*> {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("snell-expectations-" + std::to_string(::getpid()) + "-" + GetParam());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  CaseResult run(const std::string& extraHead, const std::string& capture,
                 const std::string& fragment = kFragment) {
    std::ofstream(dir_ / "r.vert") << kVertex;
    std::ofstream(dir_ / "r.frag") << fragment;
    std::ofstream(dir_ / "manifest.toml") << kManifestHead << extraHead << kManifestBody << capture;
    const std::vector<Manifest> manifests = loadManifests(dir_);
    const std::vector<Case> cases = expandCases(manifests, "");
    std::unique_ptr<Backend> backend = makeBackend(GetParam(), BackendOptions{.validation = true});
    OracleCache oracles;
    SceneCache scenes;
    ReferenceCache references;
    CaseRunner runner(*backend, oracles, scenes, references, ImageCheckOptions{dir_ / "out", ""});
    return runner.run(cases.at(0));
  }

  fs::path dir_;
};

TEST_P(CaseExpectations, FragmentValuesPassWhereTheListingIsRight) {
  const CaseResult result = run("", captures(10));
  EXPECT_EQ(result.status, Status::Pass) << result.message;
  ASSERT_EQ(result.varyings.size(), 2u);
  EXPECT_GT(result.vertices, 1000u);  // pixels covered by the sphere
  EXPECT_EQ(result.varyings[1].name, "refractview");
  EXPECT_EQ(result.varyings[1].checked, result.vertices * 3);
}

TEST_P(CaseExpectations, AConstantTheOracleDoesNotShareFails) {
  std::string edited = kFragment;
  edited.replace(edited.find("1.1;"), 4, "1.2;");
  const CaseResult result = run("", captures(10), edited);
  EXPECT_EQ(result.status, Status::Fail);
  EXPECT_GT(result.componentsFailed(), 0u);
  EXPECT_NE(result.message.find("refractview:"), std::string::npos) << result.message;
  EXPECT_NE(result.message.find("pixel ("), std::string::npos) << result.message;
}

TEST_P(CaseExpectations, AProbeWhoseLineNeverRanFails) {
  const CaseResult result = run("", captures(12));
  EXPECT_EQ(result.status, Status::Fail);
  EXPECT_NE(result.message.find("refractview: not written at"), std::string::npos)
      << result.message;
}

// The error pinned at line 2 (where sampler2d is) for both compilers.
const char* kExpectErrorAtLine2 = R"(expect = "compile-error"
[compile_error.gl]
stage = "fragment"
line  = 2
[compile_error.vk]
stage = "fragment"
line  = 2
)";

std::string withUndeclaredSampler(std::string fragment) {
  fragment.replace(fragment.find("samplerCube"), 11, "sampler2d");
  return fragment;
}

TEST_P(CaseExpectations, AnExpectedCompileErrorPassesWithTheDiagnostic) {
  const CaseResult result = run(kExpectErrorAtLine2, captures(10), withUndeclaredSampler(kFragment));
  EXPECT_EQ(result.status, Status::ExpectedCompileError) << result.message;
  EXPECT_FALSE(isFailure(result.status));
  EXPECT_NE(result.message.find("does not compile, as expected"), std::string::npos);
  // Both compilers point at line 2, where sampler2d is.
  const char* where = std::string(GetParam()) == "gl" ? "0:2(" : "r.frag:2:";
  EXPECT_NE(result.message.find(where), std::string::npos) << result.message;
  EXPECT_EQ(result.compileLog.empty(), false);
}

TEST_P(CaseExpectations, AnExpectedCompileErrorThatCompilesFails) {
  const CaseResult result = run(kExpectErrorAtLine2, captures(10));
  EXPECT_EQ(result.status, Status::Fail);
  EXPECT_NE(result.message.find("expected not to compile"), std::string::npos) << result.message;
}

// A listing that does not compile for another reason than the pinned one
// (garbage at line 6, the sampler declared right) is a failure, not a pass.
TEST_P(CaseExpectations, ADifferentCompileErrorFails) {
  std::string garbled = kFragment;
  garbled.insert(garbled.find("void main()"), "@@ garbage @@\n");
  const CaseResult result = run(kExpectErrorAtLine2, captures(10), garbled);
  EXPECT_EQ(result.status, Status::Fail) << result.message;
  EXPECT_NE(result.message.find("not with the expected error"), std::string::npos)
      << result.message;
  EXPECT_NE(result.message.find("r.frag:2"), std::string::npos) << result.message;
}

TEST_P(CaseExpectations, AnExpectedCompileErrorWithoutItsDiagnosticIsRefused) {
  EXPECT_THROW(run("expect = \"compile-error\"\n", captures(10), withUndeclaredSampler(kFragment)),
               UsageError);
}

TEST_P(CaseExpectations, NotSupportedGivesTheReasonOnThatBackendOnly) {
  const CaseResult result =
      run("not_supported = { vk = \"the reason, as the manifest gives it\" }\n", captures(10));
  if (std::string(GetParam()) == "vk") {
    EXPECT_EQ(result.status, Status::NotSupported);
    EXPECT_EQ(result.message, "the reason, as the manifest gives it");
    EXPECT_TRUE(result.varyings.empty());
  } else {
    EXPECT_EQ(result.status, Status::Pass) << result.message;
  }
}

INSTANTIATE_TEST_SUITE_P(Backends, CaseExpectations, testing::Values("gl", "vk"));

}  // namespace
}  // namespace snell
