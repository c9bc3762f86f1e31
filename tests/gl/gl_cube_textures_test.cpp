// A suite renders many cases against one environment: each is uploaded once
// per context, and again only when its texels change.
#include "backends/gl/gl_cube_textures.h"

#include <gtest/gtest.h>

#include <cmath>

#include "backends/gl/gl_context_provider.h"
#include "gl_render_test_jobs.h"

namespace snell {
namespace {

// Declared before the textures, so it outlives them: they are deleted on it.
struct CurrentContext {
  CurrentContext() : context(createGlContext(GlProviderKind::Osmesa, {})) {
    context->makeCurrent();
  }
  std::unique_ptr<GlContext> context;
};

TEST(GlCubeTextures, SameEnvironmentIsUploadedOnce) {
  CurrentContext current;
  GlCubeTextures textures;
  const CubeMap map = gltest::distinctTexelCubeMap(4, CubeFilter::Linear);
  for (int job = 0; job < 5; ++job) {
    textures.beginJob();
    textures.bind(map, 0);
  }
  EXPECT_EQ(textures.uploads(), 1u);
}

TEST(GlCubeTextures, ChangedTexelsAreUploadedAgain) {
  CurrentContext current;
  GlCubeTextures textures;
  CubeMap map = gltest::distinctTexelCubeMap(4, CubeFilter::Linear);
  textures.bind(map, 0);
  map.faces[5][7] += 0.5f;
  textures.bind(map, 0);
  EXPECT_EQ(textures.uploads(), 2u);
  // The filter is sampling state: switching it uploads nothing.
  map.filter = CubeFilter::Nearest;
  textures.bind(map, 0);
  EXPECT_EQ(textures.uploads(), 2u);
}

TEST(GlCubeTextures, EachEnvironmentHasItsOwnTexture) {
  CurrentContext current;
  GlCubeTextures textures;
  const CubeMap first = gltest::distinctTexelCubeMap(2, CubeFilter::Linear);
  const CubeMap second = gltest::distinctTexelCubeMap(2, CubeFilter::Linear);
  textures.beginJob();
  textures.bind(first, 0);
  textures.bind(second, 1);
  textures.beginJob();
  textures.bind(first, 0);
  textures.bind(second, 1);
  EXPECT_EQ(textures.uploads(), 2u);
}

TEST(GlCubeTextures, HashSeesOneTexelAndTheSize) {
  const CubeMap map = gltest::distinctTexelCubeMap(3, CubeFilter::Linear);
  CubeMap changed = map;
  EXPECT_EQ(cubeMapHash(changed), cubeMapHash(map));
  changed.faces[2][13] = std::nextafter(changed.faces[2][13], 1.0f);
  EXPECT_NE(cubeMapHash(changed), cubeMapHash(map));
  CubeMap empty;
  CubeMap sized;
  sized.size = 1;
  EXPECT_NE(cubeMapHash(empty), cubeMapHash(sized));
}

}  // namespace
}  // namespace snell
