// Legacy listings on the compatibility context read fixed-function state
// set from values given under the built-ins' names (gl_legacy_state.h);
// GL's derived state is the one snell computes for Vulkan and the oracles
// (core/legacy_builtins.h), bit for bit on llvmpipe.
#include <gtest/gtest.h>

#include "backends/gl/gl_backend.h"
#include "core/errors.h"
#include "core/legacy_builtins.h"
#include "core/scene.h"
#include "gl_render_test_jobs.h"

namespace snell {
namespace {

using gltest::value;

const char* const kLegacyVertex = R"(varying vec4 eye;
varying vec3 normal;
varying vec4 clip;
varying vec4 coords0;
varying vec4 coords1;
void main() {
  eye = gl_ModelViewMatrix * gl_Vertex;
  normal = gl_NormalMatrix * gl_Normal;
  coords0 = gl_TextureMatrix[0] * gl_MultiTexCoord0;
  coords1 = gl_TextureMatrix[1] * gl_MultiTexCoord1;
  clip = ftransform();
  gl_Position = clip;
}
)";

CaptureJob legacyJob() {
  CaptureJob job;
  job.program = gltest::vertexOnly(kLegacyVertex, Profile::Compatibility, "probes/legacy.vert");
  job.varyings = {"eye", "normal", "clip", "coords0", "coords1"};
  job.vertexCount = 2;
  gltest::addAttribute(job, gltest::attribute("gl_Vertex", 4, {1, 2, 3, 1, -1, 0, 2, 1}));
  gltest::addAttribute(job, gltest::attribute("gl_Normal", 3, {1, 1, 1, 0, 0, 1}));
  gltest::addAttribute(job, gltest::attribute("gl_MultiTexCoord0", 2, {1, 2, 3, 4}));
  gltest::addAttribute(job, gltest::attribute("gl_MultiTexCoord1", 4, {1, 0, 0, 1, 0, 1, 0, 1}));
  // A scale and a move, a simple perspective, a quarter turn and a move:
  // every result below is exact in fp32.
  job.uniforms["gl_ModelViewMatrix"] =
      value(ValueType::Mat4, {2, 0, 0, 0, 0, 4, 0, 0, 0, 0, 0.5f, 0, 3, 0, 0, 1});
  job.uniforms["gl_ProjectionMatrix"] =
      value(ValueType::Mat4, {0.25f, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, -1, 0, 0, 1, 0});
  job.uniforms["gl_TextureMatrix[0]"] =
      value(ValueType::Mat4, {2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 1});
  job.uniforms["gl_TextureMatrix[1]"] =
      value(ValueType::Mat4, {0, 1, 0, 0, -1, 0, 0, 0, 0, 0, 1, 0, 5, 6, 7, 1});
  return job;
}

TEST(GlLegacyState, MatricesAndArraysComeFromValuesUnderGlNames) {
  auto backend = makeGlBackend({});
  const CaptureOutcome outcome = backend->captureVertexOutputs(legacyJob());
  ASSERT_TRUE(outcome.compile.ok) << outcome.compile.log;
  EXPECT_EQ(gltest::varyingNamed(outcome, "eye").data,
            (std::vector<float>{5, 8, 1.5f, 1, 1, 0, 1, 1}));
  EXPECT_EQ(gltest::varyingNamed(outcome, "normal").data,
            (std::vector<float>{0.5f, 0.25f, 2, 0, 0, 2}));
  EXPECT_EQ(gltest::varyingNamed(outcome, "clip").data,
            (std::vector<float>{1.25f, 8, 2.5f, -1.5f, 0.25f, 0, 2, -1}));
  // A two-component array gives (s, t, 0, 1), as GL fills it.
  EXPECT_EQ(gltest::varyingNamed(outcome, "coords0").data,
            (std::vector<float>{2, 4, 0, 1, 6, 8, 0, 1}));
  EXPECT_EQ(gltest::varyingNamed(outcome, "coords1").data,
            (std::vector<float>{5, 7, 7, 1, 4, 6, 7, 1}));
}

TEST(GlLegacyState, StateAJobLeavesOutIsGlsInitialStateNotThePreviousJobs) {
  auto backend = makeGlBackend({});
  ASSERT_TRUE(backend->captureVertexOutputs(legacyJob()).compile.ok);
  CaptureJob bare = legacyJob();
  bare.uniforms.clear();
  bare.attributes.erase("gl_Normal");
  bare.attributes.erase("gl_MultiTexCoord1");
  const CaptureOutcome outcome = backend->captureVertexOutputs(bare);
  ASSERT_TRUE(outcome.compile.ok) << outcome.compile.log;
  // Identity matrices, the initial normal (0, 0, 1) and texture coordinate (0, 0, 0, 1).
  EXPECT_EQ(gltest::varyingNamed(outcome, "eye").data,
            (std::vector<float>{1, 2, 3, 1, -1, 0, 2, 1}));
  EXPECT_EQ(gltest::varyingNamed(outcome, "normal").data, (std::vector<float>{0, 0, 1, 0, 0, 1}));
  EXPECT_EQ(gltest::varyingNamed(outcome, "coords1").data,
            (std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1}));
}

TEST(GlLegacyState, AMatrixOfTheWrongTypeIsAUsageError) {
  auto backend = makeGlBackend({});
  CaptureJob job = legacyJob();
  job.uniforms["gl_TextureMatrix[1]"] = value(ValueType::Mat3, std::vector<float>(9, 1.0f));
  EXPECT_THROW(backend->captureVertexOutputs(job), UsageError);
  job = legacyJob();
  job.attributes["gl_Normal"] = gltest::attribute("gl_Normal", 4, std::vector<float>(8, 1.0f));
  EXPECT_THROW(backend->captureVertexOutputs(job), UsageError);
}

TEST(GlLegacyState, CoreListingsAfterLegacyOnesAreUntouched) {
  auto backend = makeGlBackend({});
  ASSERT_TRUE(backend->captureVertexOutputs(legacyJob()).compile.ok);
  CaptureJob core;
  core.program = gltest::vertexOnly(
      "#version 140\nin vec4 a;\nout vec4 y;\n"
      "void main() { y = a; gl_Position = vec4(0.0); }\n");
  gltest::addAttribute(core, gltest::attribute("a", 4, {4, 3, 2, 1}));
  core.uniforms["gl_ModelViewMatrix"] = legacyJob().uniforms.at("gl_ModelViewMatrix");
  core.varyings = {"y"};
  core.vertexCount = 1;
  const CaptureOutcome outcome = backend->captureVertexOutputs(core);
  ASSERT_TRUE(outcome.compile.ok) << outcome.compile.log;
  EXPECT_EQ(outcome.varyings.at(0).data, (std::vector<float>{4, 3, 2, 1}));
}

TEST(GlLegacyState, RendersWhereFtransformPutsTheVertices) {
  auto backend = makeGlBackend({});
  RenderJob job;
  job.program = gltest::program("void main() { gl_Position = ftransform(); }\n",
                                "void main() { gl_FragColor = vec4(1.0, 0.5, 0.25, 1.0); }\n",
                                Profile::Compatibility);
  gltest::Triangles square;
  square.fullScreen(0.0f, {0, 0, 0, 0});
  std::vector<float> vertices;
  for (std::size_t k = 0; k < square.positions.size(); k += 3)
    vertices.insert(vertices.end(), {square.positions[k], square.positions[k + 1], 0.0f, 1.0f});
  job.attributes["gl_Vertex"] = gltest::attribute("gl_Vertex", 4, vertices);
  job.indices = square.indices;
  job.width = 4;
  job.height = 4;
  // Halved and moved left: the square covers the left half of the target.
  job.uniforms["gl_ModelViewMatrix"] =
      value(ValueType::Mat4, {0.5f, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, -0.5f, 0, 0, 1});
  job.uniforms["gl_ProjectionMatrix"] =
      value(ValueType::Mat4, {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1});
  const RenderOutcome outcome = backend->render(job);
  ASSERT_TRUE(outcome.compile.ok) << outcome.compile.log;
  for (int y = 0; y < 4; ++y) {
    EXPECT_EQ(gltest::pixel(outcome.image, 1, y), (gltest::Rgba{1, 0.5f, 0.25f, 1})) << y;
    EXPECT_EQ(gltest::pixel(outcome.image, 2, y), (gltest::Rgba{0, 0, 0, 0})) << y;
  }
}

// What Mesa derives (gl_NormalMatrix, gl_ModelViewProjectionMatrix) is what
// snell binds on Vulkan and gives the oracles, for every scene's matrices.
TEST(GlLegacyState, DerivedStateMatchesSnellsForEveryScene) {
  const char* const derived = R"(varying vec3 n0;
varying vec3 n1;
varying vec3 n2;
varying vec4 m0;
varying vec4 m1;
varying vec4 m2;
varying vec4 m3;
void main() {
  n0 = gl_NormalMatrix[0]; n1 = gl_NormalMatrix[1]; n2 = gl_NormalMatrix[2];
  m0 = gl_ModelViewProjectionMatrix[0]; m1 = gl_ModelViewProjectionMatrix[1];
  m2 = gl_ModelViewProjectionMatrix[2]; m3 = gl_ModelViewProjectionMatrix[3];
  gl_Position = gl_Vertex;
}
)";
  auto backend = makeGlBackend({});
  for (const char* name : {"sphere", "sweep", "torus"}) {
    const Scene scene = makeScene(name);
    CaptureJob job;
    job.program = gltest::vertexOnly(derived, Profile::Compatibility);
    job.varyings = {"n0", "n1", "n2", "m0", "m1", "m2", "m3"};
    job.vertexCount = 1;
    job.uniforms["gl_ModelViewMatrix"] = scene.values.at("modelview");
    job.uniforms["gl_ProjectionMatrix"] = scene.values.at("projection");
    gltest::addAttribute(job, gltest::attribute("gl_Vertex", 4, {0, 0, 0, 1}));
    const CaptureOutcome outcome = backend->captureVertexOutputs(job);
    ASSERT_TRUE(outcome.compile.ok) << outcome.compile.log;
    std::vector<float> normal, product;
    for (int k = 0; k < 3; ++k)
      for (float x : outcome.varyings.at(static_cast<std::size_t>(k)).data) normal.push_back(x);
    for (int k = 3; k < 7; ++k)
      for (float x : outcome.varyings.at(static_cast<std::size_t>(k)).data) product.push_back(x);
    const UniformMap ours = withDerivedLegacyState(job.uniforms);
    EXPECT_EQ(normal, ours.at("gl_NormalMatrix").data) << name;
    EXPECT_EQ(product, ours.at("gl_ModelViewProjectionMatrix").data) << name;
  }
}

}  // namespace
}  // namespace snell
