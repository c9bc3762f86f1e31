// Cube map lookups through a render, validation on. Directions come from
// the cube map rules (the major axis picks the face; s and t come from the
// other two), written here independently of any CPU sampler in the harness.
// The program has loose uniforms in both stages and a samplerCube, so these
// renders also cover the descriptor bindings glslang gives such programs.
#include <gtest/gtest.h>

#include <array>
#include <random>
#include <string>

#include "backends/vk/vk_backend.h"
#include "core/errors.h"
#include "render_geometry.h"

namespace snell {
namespace {

using Rgba = std::array<float, 4>;

Backend& backend() {
  static std::unique_ptr<Backend> shared = makeVkBackend(BackendOptions{.validation = true});
  return *shared;
}

CubeMap randomCube(int size, CubeFilter filter, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  CubeMap cube;
  cube.size = size;
  cube.filter = filter;
  for (std::vector<float>& face : cube.faces) {
    face.resize(static_cast<std::size_t>(size * size * 4));
    for (float& value : face) value = unit(random);
  }
  return cube;
}

Rgba texel(const CubeMap& cube, int face, int i, int j) {
  const float* at = &cube.faces[face][static_cast<std::size_t>((j * cube.size + i) * 4)];
  return {at[0], at[1], at[2], at[3]};
}

// The direction that lands on (s, t) of `face` (+X, -X, +Y, -Y, +Z, -Z),
// from the inverse of the cube map face selection table, with |major| = 1.
std::array<float, 3> directionAt(int face, double s, double t) {
  const auto sc = static_cast<float>(2 * s - 1);
  const auto tc = static_cast<float>(2 * t - 1);
  switch (face) {
    case 0:
      return {1, -tc, -sc};
    case 1:
      return {-1, -tc, sc};
    case 2:
      return {sc, 1, tc};
    case 3:
      return {sc, -1, -tc};
    case 4:
      return {sc, -tc, 1};
    default:
      return {-sc, -tc, -1};
  }
}

// A full-screen draw whose every pixel is texture(Env, Direction).
RenderJob cubeLookupJob() {
  RenderJob job;
  job.program.vertex = R"(#version 140
in vec4 Position;
uniform float Depth;
void main() { gl_Position = vec4(Position.xy, Depth, 1.0); }
)";
  job.program.fragment = R"(#version 140
uniform samplerCube Env;
uniform vec3 Direction;
out vec4 FragColor;
void main() { FragColor = texture(Env, Direction); }
)";
  job.program.vertexPath = "probes/cube_lookup.vert";
  job.program.fragmentPath = "probes/cube_lookup.frag";
  vktest::Mesh screen;
  vktest::addRectangle(screen, -1, -1, 1, 1, 0.0f);
  job.attributes["Position"] = screen.positions;
  job.indices = screen.indices;
  job.uniforms["Depth"] = Value{ValueType::Float, {0.5f}};
  job.width = 2;
  job.height = 2;
  return job;
}

class VkRenderCube : public ::testing::Test {
 protected:
  Rgba lookUp(const CubeMap& cube, const std::array<float, 3>& direction) {
    job_.cubeMaps["Env"] = &cube;
    job_.uniforms["Direction"] = Value{ValueType::Vec3, {direction.begin(), direction.end()}};
    const RenderOutcome outcome = backend().render(job_);
    EXPECT_TRUE(outcome.compile.ok) << outcome.compile.log;
    if (outcome.image.pixels.empty()) return {};
    const float* at = outcome.image.at(1, 1);
    return {at[0], at[1], at[2], at[3]};
  }

  RenderJob job_ = cubeLookupJob();
};

TEST_F(VkRenderCube, NearestAtEachFaceCentreIsThatFacesCentreTexel) {
  const CubeMap cube = randomCube(5, CubeFilter::Nearest, 1);
  const std::array<std::array<float, 3>, 6> axes = {
      {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}}};
  for (int face = 0; face < 6; ++face) {
    EXPECT_EQ(lookUp(cube, axes[face]), texel(cube, face, 2, 2)) << "face " << face;
  }
}

TEST_F(VkRenderCube, NearestAtEveryTexelCentreIsThatTexel) {
  // Row j of the face data must be the image's row j, and each face the right layer.
  const CubeMap cube = randomCube(3, CubeFilter::Nearest, 2);
  for (int face = 0; face < 6; ++face) {
    for (int j = 0; j < cube.size; ++j) {
      for (int i = 0; i < cube.size; ++i) {
        const double s = (i + 0.5) / cube.size, t = (j + 0.5) / cube.size;
        EXPECT_EQ(lookUp(cube, directionAt(face, s, t)), texel(cube, face, i, j))
            << "face " << face << " texel " << i << ", " << j;
      }
    }
  }
}

TEST_F(VkRenderCube, LinearAtATexelCornerAveragesTheFourTexels) {
  const CubeMap cube = randomCube(4, CubeFilter::Linear, 3);
  for (int face = 0; face < 6; ++face) {
    for (int l = 1; l < cube.size; ++l) {
      for (int k = 1; k < cube.size; ++k) {
        const Rgba got =
            lookUp(cube, directionAt(face, double(k) / cube.size, double(l) / cube.size));
        for (int c = 0; c < 4; ++c) {
          const double expected =
              (double(texel(cube, face, k - 1, l - 1)[c]) + texel(cube, face, k, l - 1)[c] +
               texel(cube, face, k - 1, l)[c] + texel(cube, face, k, l)[c]) /
              4;
          EXPECT_NEAR(got[c], expected, 1e-6)
              << "face " << face << " corner " << k << ", " << l << " channel " << c;
        }
      }
    }
  }
}

TEST_F(VkRenderCube, BothStagesReadTheSharedUniformBlock) {
  const CubeMap cube = randomCube(3, CubeFilter::Nearest, 9);
  job_.clearColor = {-1, -1, -1, -1};
  // Depth beyond the far plane clips the whole draw: only a vertex stage
  // that really reads Depth leaves the clear colour.
  job_.uniforms["Depth"] = Value{ValueType::Float, {2.0f}};
  EXPECT_EQ(lookUp(cube, {0, -1, 0}), (Rgba{-1, -1, -1, -1}));
  job_.uniforms["Depth"] = Value{ValueType::Float, {0.5f}};
  EXPECT_EQ(lookUp(cube, {0, -1, 0}), texel(cube, 3, 1, 1));
}

TEST_F(VkRenderCube, AMapChangedInPlaceIsUploadedAgain) {
  CubeMap cube = randomCube(3, CubeFilter::Nearest, 4);
  const std::array<float, 3> plusX = {1, 0, 0};
  EXPECT_EQ(lookUp(cube, plusX), texel(cube, 0, 1, 1));
  float* centre = &cube.faces[0][(1 * 3 + 1) * 4];
  for (int c = 0; c < 4; ++c) centre[c] = 2.0f + static_cast<float>(c);
  EXPECT_EQ(lookUp(cube, plusX), (Rgba{2, 3, 4, 5}));
}

TEST_F(VkRenderCube, ASamplerWithoutACubeMapIsAUsageErrorNamingIt) {
  job_.uniforms["Direction"] = Value{ValueType::Vec3, {1, 0, 0}};
  const CubeMap other = randomCube(2, CubeFilter::Nearest, 5);
  job_.cubeMaps["Environment"] = &other;  // not the name the program uses
  try {
    backend().render(job_);
    FAIL() << "a render without a cube map for 'Env' was accepted";
  } catch (const UsageError& error) {
    EXPECT_NE(std::string(error.what()).find("'Env'"), std::string::npos) << error.what();
  }
}

TEST_F(VkRenderCube, MalformedAndNonSeamlessMapsAreUsageErrors) {
  CubeMap shortFace = randomCube(3, CubeFilter::Nearest, 6);
  shortFace.faces[4].pop_back();
  EXPECT_THROW(lookUp(shortFace, {1, 0, 0}), UsageError);
  CubeMap seams = randomCube(3, CubeFilter::Linear, 7);
  seams.seamless = false;
  EXPECT_THROW(lookUp(seams, {1, 0, 0}), UsageError);
}

TEST(VkRenderTearDown, LeavesNothingForTheValidationLayerToReport) {
  // Messages during destruction have no call to be thrown from, so the
  // backend prints them to stderr; here they must not appear at all.
  ::testing::internal::CaptureStderr();
  {
    auto own = makeVkBackend(BackendOptions{.validation = true});
    RenderJob job = cubeLookupJob();
    const CubeMap cube = randomCube(2, CubeFilter::Linear, 8);
    job.cubeMaps["Env"] = &cube;
    job.uniforms["Direction"] = Value{ValueType::Vec3, {0, 0, 1}};
    const RenderOutcome outcome = own->render(job);
    EXPECT_TRUE(outcome.compile.ok) << outcome.compile.log;
    EXPECT_EQ(outcome.image.width, 2);
  }
  const std::string stderrText = ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(stderrText.find("Vulkan validation"), std::string::npos) << stderrText;
}

}  // namespace
}  // namespace snell
