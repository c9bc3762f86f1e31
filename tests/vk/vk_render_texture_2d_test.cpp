// sampler2D lookups through a Vulkan render, validation on. Each lookup
// lands on the texels backend.h promises for RenderJob::textures2D:
// image.at(i, j) covers u in [i/width, (i+1)/width] and v in [j/height,
// (j+1)/height], LINEAR filtering, REPEAT wrapping. Texel colours are
// multiples of 1/64, so a texel and the average of two or four are exact.
#include <gtest/gtest.h>

#include <array>
#include <initializer_list>
#include <string>

#include "backends/vk/vk_backend.h"
#include "core/errors.h"
#include "render_geometry.h"

namespace snell {
namespace {

using Rgba = std::array<float, 4>;

constexpr int kWidth = 4;
constexpr int kHeight = 2;

Backend& backend() {
  static std::unique_ptr<Backend> shared = makeVkBackend(BackendOptions{.validation = true});
  return *shared;
}

Rgba texelColour(int i, int j) {
  return {static_cast<float>(i + 1) / 8, static_cast<float>(j + 1) / 8,
          static_cast<float>(2 * i + j + 1) / 16, 0.5f};
}

Image distinctTexelImage() {
  Image image(kWidth, kHeight);
  for (int j = 0; j < kHeight; ++j)
    for (int i = 0; i < kWidth; ++i) {
      const Rgba colour = texelColour(i, j);
      std::copy(colour.begin(), colour.end(), image.at(i, j));
    }
  return image;
}

Rgba average(std::initializer_list<Rgba> texels) {
  Rgba sum{};
  for (const Rgba& texel : texels)
    for (std::size_t c = 0; c < 4; ++c) sum[c] += texel[c] / static_cast<float>(texels.size());
  return sum;
}

// A full-screen draw whose every pixel is texture(Tex, Coord), with loose
// uniforms in both stages so the sampler shares a set with the block.
RenderJob lookupJob() {
  RenderJob job;
  job.program.vertex = R"(#version 140
in vec4 Position;
uniform float Depth;
void main() { gl_Position = vec4(Position.xy, Depth, 1.0); }
)";
  job.program.fragment = R"(#version 140
uniform sampler2D Tex;
uniform vec2 Coord;
out vec4 FragColor;
void main() { FragColor = texture(Tex, Coord); }
)";
  job.program.vertexPath = "probes/lookup_2d.vert";
  job.program.fragmentPath = "probes/lookup_2d.frag";
  vktest::Mesh screen;
  vktest::addRectangle(screen, -1, -1, 1, 1, 0.0f);
  job.attributes["Position"] = screen.positions;
  job.indices = screen.indices;
  job.uniforms["Depth"] = Value{ValueType::Float, {0.5f}};
  job.width = 2;
  job.height = 2;
  return job;
}

class VkRenderTexture2D : public ::testing::Test {
 protected:
  Rgba lookUp(const Image& image, std::array<float, 2> coord) {
    job_.textures2D["Tex"] = &image;
    job_.uniforms["Coord"] = Value{ValueType::Vec2, {coord[0], coord[1]}};
    const RenderOutcome outcome = backend().render(job_);
    EXPECT_TRUE(outcome.compile.ok) << outcome.compile.log;
    if (outcome.image.pixels.empty()) return {};
    const float* at = outcome.image.at(1, 1);
    return {at[0], at[1], at[2], at[3]};
  }

  void expectNear(std::array<float, 2> coord, const Rgba& expected, const std::string& where) {
    const Rgba got = lookUp(image_, coord);
    for (std::size_t c = 0; c < 4; ++c)
      EXPECT_NEAR(got[c], expected[c], 1e-6) << where << " channel " << c;
  }

  RenderJob job_ = lookupJob();
  Image image_ = distinctTexelImage();
};

TEST_F(VkRenderTexture2D, TexelCentresReturnTheirTexelRowJIsVJ) {
  for (int j = 0; j < kHeight; ++j)
    for (int i = 0; i < kWidth; ++i)
      EXPECT_EQ(lookUp(image_, {(i + 0.5f) / kWidth, (j + 0.5f) / kHeight}), texelColour(i, j))
          << "texel " << i << ", " << j;
}

TEST_F(VkRenderTexture2D, LinearHalfWayBetweenCentresAveragesTheTexels) {
  expectNear({2.0f / kWidth, 0.5f / kHeight}, average({texelColour(1, 0), texelColour(2, 0)}),
             "between columns 1 and 2");
  expectNear({1.0f / kWidth, 1.0f / kHeight},
             average({texelColour(0, 0), texelColour(1, 0), texelColour(0, 1), texelColour(1, 1)}),
             "at the corner of four texels");
}

TEST_F(VkRenderTexture2D, RepeatWrapsTheFootprintAndTheCoordinate) {
  expectNear({0.0f, 0.5f / kHeight}, average({texelColour(kWidth - 1, 0), texelColour(0, 0)}),
             "u = 0");
  expectNear({1.5f / kWidth, 0.0f}, average({texelColour(1, kHeight - 1), texelColour(1, 0)}),
             "v = 0");
  EXPECT_EQ(lookUp(image_, {1.0f + 2.5f / kWidth, -1.0f + 0.5f / kHeight}), texelColour(2, 0));
}

TEST_F(VkRenderTexture2D, CubeMapAndTexture2DInOneProgramGetTheirOwnDescriptors) {
  job_.program.fragment = R"(#version 140
uniform samplerCube Env;
uniform sampler2D Tex;
uniform vec2 Coord;
out vec4 FragColor;
void main() { FragColor = texture(Tex, Coord) + texture(Env, vec3(0.0, 0.0, 1.0)); }
)";
  job_.program.fragmentPath = "probes/lookup_2d_and_cube.frag";
  CubeMap cube;
  cube.size = 1;
  cube.filter = CubeFilter::Nearest;
  for (int face = 0; face < 6; ++face)
    cube.faces[static_cast<std::size_t>(face)] = {0.25f * static_cast<float>(face), 0, 0, 0};
  job_.cubeMaps["Env"] = &cube;
  const Rgba texel = texelColour(3, 1);
  expectNear({3.5f / kWidth, 1.5f / kHeight}, {texel[0] + 1.0f, texel[1], texel[2], texel[3]},
             "texel (3, 1) plus +Z");
}

TEST_F(VkRenderTexture2D, AnImageChangedInPlaceIsUploadedAgain) {
  const std::array<float, 2> centre = {0.5f / kWidth, 0.5f / kHeight};
  EXPECT_EQ(lookUp(image_, centre), texelColour(0, 0));
  image_.at(0, 0)[0] = 0.75f;
  EXPECT_EQ(lookUp(image_, centre)[0], 0.75f);
}

TEST_F(VkRenderTexture2D, ASamplerWithoutATextureIsAUsageErrorNamingIt) {
  job_.uniforms["Coord"] = Value{ValueType::Vec2, {0.5f, 0.5f}};
  job_.textures2D["Decal"] = &image_;  // not the name the program uses
  try {
    backend().render(job_);
    FAIL() << "a render without a 2D texture for 'Tex' was accepted";
  } catch (const UsageError& error) {
    EXPECT_NE(std::string(error.what()).find("'Tex'"), std::string::npos) << error.what();
  }
}

TEST_F(VkRenderTexture2D, AnArrayedSamplerIsNotTakenForASampler2D) {
  job_.program.fragment = R"(#version 140
uniform sampler2DArray Tex;
uniform vec2 Coord;
out vec4 FragColor;
void main() { FragColor = texture(Tex, vec3(Coord, 0.0)); }
)";
  job_.program.fragmentPath = "probes/lookup_2d_array.frag";
  try {
    lookUp(image_, {0.5f, 0.5f});
    FAIL() << "a sampler2DArray was bound to a 2D texture";
  } catch (const UsageError& error) {
    EXPECT_NE(std::string(error.what()).find("'Tex'"), std::string::npos) << error.what();
  }
}

TEST_F(VkRenderTexture2D, AMalformedImageIsAUsageError) {
  Image shortImage = distinctTexelImage();
  shortImage.pixels.pop_back();
  EXPECT_THROW(lookUp(shortImage, {0.5f, 0.5f}), UsageError);
}

}  // namespace
}  // namespace snell
