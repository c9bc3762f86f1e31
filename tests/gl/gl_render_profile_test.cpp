// Legacy listings (GLSL 1.20: varying, textureCube, gl_FragColor) render on
// the compatibility context.
#include <gtest/gtest.h>

#include "backends/gl/gl_api.h"
#include "backends/gl/gl_backend.h"
#include "gl_render_test_jobs.h"

namespace snell {
namespace {

const char* const kLegacyVertex = R"(#version 120
attribute vec3 position;
uniform vec3 direction;
varying vec3 dir;
void main() {
  dir = direction;
  gl_Position = vec4(position, 1.0);
}
)";

const char* const kLegacyFragment = R"(#version 120
uniform samplerCube Env;
varying vec3 dir;
void main() { gl_FragColor = textureCube(Env, dir); }
)";

// The backend leaves the context of its last call current.
bool currentContextIsCompatibility() {
  GLint mask = 0;
  glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &mask);
  return (mask & GL_CONTEXT_COMPATIBILITY_PROFILE_BIT) != 0;
}

TEST(GlRenderProfile, LegacyCubeMapListingRendersOnCompatibilityContext) {
  auto backend = makeGlBackend({});
  const CubeMap map = gltest::distinctTexelCubeMap(3, CubeFilter::Nearest);
  RenderJob job = gltest::lookupJob(map, {0, 0, 0});
  job.program = gltest::program(kLegacyVertex, kLegacyFragment, Profile::Compatibility);
  job.uniforms.clear();
  job.uniforms["direction"] = gltest::value(ValueType::Vec3, {0, -1, 0});

  const RenderOutcome outcome = backend->render(job);
  ASSERT_TRUE(outcome.compile.ok) << outcome.compile.log;
  EXPECT_TRUE(currentContextIsCompatibility());
  EXPECT_EQ(gltest::pixelsOtherThan(outcome.image, gltest::texelColour(3, 1, 1), 0, 0, 4, 4), 0);
}

TEST(GlRenderProfile, CoreAndCompatibilityRendersInterleave) {
  auto backend = makeGlBackend({});
  const CubeMap map = gltest::distinctTexelCubeMap(3, CubeFilter::Nearest);
  RenderJob legacy = gltest::lookupJob(map, {0, 0, 0});
  legacy.program = gltest::program(kLegacyVertex, kLegacyFragment, Profile::Compatibility);
  legacy.uniforms.clear();
  legacy.uniforms["direction"] = gltest::value(ValueType::Vec3, {1, 0, 0});
  const RenderJob core = gltest::lookupJob(map, {0, 0, -1});
  for (int round = 0; round < 3; ++round) {
    EXPECT_EQ(gltest::pixel(backend->render(legacy).image, 1, 2), gltest::texelColour(0, 1, 1))
        << "round " << round;
    EXPECT_TRUE(currentContextIsCompatibility());
    EXPECT_EQ(gltest::pixel(backend->render(core).image, 1, 2), gltest::texelColour(5, 1, 1))
        << "round " << round;
    EXPECT_FALSE(currentContextIsCompatibility());
  }
}

}  // namespace
}  // namespace snell
