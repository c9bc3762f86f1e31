// sampler2D lookups in a fragment shader land on the texels backend.h
// promises for RenderJob::textures2D: image.at(i, j) covers s in
// [i/width, (i+1)/width] and t in [j/height, (j+1)/height], LINEAR
// filtering, REPEAT wrapping, texture units after the cube maps.
#include <gtest/gtest.h>

#include <array>
#include <stdexcept>
#include <string>

#include "backends/gl/gl_api.h"
#include "backends/gl/gl_backend.h"
#include "core/errors.h"
#include "gl_render_test_jobs.h"

namespace snell {
namespace {

using gltest::Rgba;

constexpr int kWidth = 4;
constexpr int kHeight = 2;

// Multiples of 1/64 well inside [0, 1]: a texel, the average of two and of
// four are exact in float, whatever order the filter adds them in, and no
// two texels share a colour.
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

const char* const kLookup2D = R"(#version 140
uniform sampler2D Tex;
uniform vec2 coord;
out vec4 FragColor;
void main() { FragColor = texture(Tex, coord); }
)";

RenderJob lookupJob(const Image& image, std::array<float, 2> coord) {
  gltest::Triangles quad;
  quad.fullScreen(0.5f, {0, 0, 0, 0});
  RenderJob job;
  job.program = gltest::program(gltest::kPositionVertex, kLookup2D);
  job.attributes["position"] = gltest::attribute("position", 3, quad.positions);
  job.indices = quad.indices;
  job.uniforms["coord"] = gltest::value(ValueType::Vec2, {coord[0], coord[1]});
  job.textures2D["Tex"] = &image;
  job.width = 4;
  job.height = 4;
  return job;
}

Rgba render(Backend& backend, const RenderJob& job) {
  const RenderOutcome outcome = backend.render(job);
  if (!outcome.compile.ok) throw std::runtime_error(outcome.compile.log);
  // The coordinate is uniform, so every pixel must agree.
  const Rgba first = gltest::pixel(outcome.image, 0, 0);
  EXPECT_EQ(gltest::pixelsOtherThan(outcome.image, first, 0, 0, 4, 4), 0);
  return first;
}

void expectNear(const Rgba& got, const Rgba& expected, const std::string& where) {
  for (std::size_t c = 0; c < 4; ++c)
    EXPECT_NEAR(got[c], expected[c], 1e-6) << where << " channel " << c;
}

TEST(GlRenderTexture2D, TexelCentresReturnTheirTexelRowJIsTJ) {
  auto backend = makeGlBackend({});
  const Image image = distinctTexelImage();
  for (int j = 0; j < kHeight; ++j)
    for (int i = 0; i < kWidth; ++i) {
      const std::array<float, 2> centre = {(i + 0.5f) / kWidth, (j + 0.5f) / kHeight};
      EXPECT_EQ(render(*backend, lookupJob(image, centre)), texelColour(i, j))
          << "texel " << i << ", " << j;
    }
}

// Half way between texel centres the LINEAR weights are exactly 1/2, which
// llvmpipe's 8-bit filter weights hold exactly.
TEST(GlRenderTexture2D, LinearHalfWayBetweenCentresAveragesTheTexels) {
  auto backend = makeGlBackend({});
  const Image image = distinctTexelImage();
  expectNear(render(*backend, lookupJob(image, {2.0f / kWidth, 0.5f / kHeight})),
             average({texelColour(1, 0), texelColour(2, 0)}), "between columns 1 and 2");
  expectNear(render(*backend, lookupJob(image, {1.0f / kWidth, 1.0f / kHeight})),
             average({texelColour(0, 0), texelColour(1, 0), texelColour(0, 1), texelColour(1, 1)}),
             "at the corner of four texels");
}

TEST(GlRenderTexture2D, RepeatWrapsTheFootprintAndTheCoordinate) {
  auto backend = makeGlBackend({});
  const Image image = distinctTexelImage();
  // At s = 0 the footprint is the last column and the first; at t = 0 the
  // last row and the first.
  expectNear(render(*backend, lookupJob(image, {0.0f, 0.5f / kHeight})),
             average({texelColour(kWidth - 1, 0), texelColour(0, 0)}), "s = 0");
  expectNear(render(*backend, lookupJob(image, {1.5f / kWidth, 0.0f})),
             average({texelColour(1, kHeight - 1), texelColour(1, 0)}), "t = 0");
  // A coordinate beyond 1 or below 0 lands where its fraction does.
  EXPECT_EQ(render(*backend, lookupJob(image, {1.0f + 2.5f / kWidth, -1.0f + 0.5f / kHeight})),
            texelColour(2, 0));
}

TEST(GlRenderTexture2D, CubeMapAndTexture2DInOneProgramUseTheirOwnUnits) {
  auto backend = makeGlBackend({});
  const Image image = distinctTexelImage();
  const CubeMap map = gltest::distinctTexelCubeMap(3, CubeFilter::Nearest);
  RenderJob job = lookupJob(image, {2.5f / kWidth, 1.5f / kHeight});
  job.program.fragment = R"(#version 140
uniform sampler2D Tex;
uniform samplerCube Env;
uniform vec2 coord;
uniform vec3 dir;
out vec4 FragColor;
void main() { FragColor = texture(Tex, coord) + texture(Env, dir); }
)";
  job.uniforms["dir"] = gltest::value(ValueType::Vec3, {0, 0, 1});
  job.cubeMaps["Env"] = &map;
  const Rgba texel = texelColour(2, 1), cube = gltest::texelColour(4, 1, 1);
  expectNear(render(*backend, job),
             {texel[0] + cube[0], texel[1] + cube[1], texel[2] + cube[2], texel[3] + cube[3]},
             "2D texel (2, 1) plus +Z centre");
  // The render puts back no texture bound, on any unit it used.
  ASSERT_NE(currentGlFunctions, nullptr);
  for (int unit = 0; unit < 2; ++unit) {
    glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
    GLint bound2D = -1, boundCube = -1;
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &bound2D);
    glGetIntegerv(GL_TEXTURE_BINDING_CUBE_MAP, &boundCube);
    EXPECT_EQ(bound2D, 0) << "unit " << unit;
    EXPECT_EQ(boundCube, 0) << "unit " << unit;
  }
  glActiveTexture(GL_TEXTURE0);
}

// Until set, every sampler is on unit 0, and GL refuses a draw whose
// samplers of different types share a unit, even one that rasterises
// nothing: a capture of such a program must still run.
TEST(GlRenderTexture2D, CaptureOfAProgramWithBothSamplerKindsRuns) {
  auto backend = makeGlBackend({});
  CaptureJob job;
  job.program = gltest::program(R"(#version 140
in vec3 position;
out vec3 P;
void main() { P = position * 2.0; gl_Position = vec4(position, 1.0); }
)",
                                R"(#version 140
uniform sampler2D Tex;
uniform samplerCube Env;
in vec3 P;
out vec4 FragColor;
void main() { FragColor = texture(Tex, P.xy) + texture(Env, P); }
)");
  gltest::addAttribute(job, gltest::attribute("position", 3, {1, 2, 3, 4, 5, 6}));
  job.varyings = {"P"};
  job.vertexCount = 2;
  const CaptureOutcome outcome = backend->captureVertexOutputs(job);
  ASSERT_TRUE(outcome.compile.ok) << outcome.compile.log;
  EXPECT_EQ(gltest::varyingNamed(outcome, "P").data, (std::vector<float>{2, 4, 6, 8, 10, 12}));
}

TEST(GlRenderTexture2D, ChangedTexelsInTheSameImageAreUploadedAgain) {
  auto backend = makeGlBackend({});
  Image image = distinctTexelImage();
  const std::array<float, 2> centre = {0.5f / kWidth, 0.5f / kHeight};
  EXPECT_EQ(render(*backend, lookupJob(image, centre)), texelColour(0, 0));
  image.at(0, 0)[0] = 0.75f;
  EXPECT_EQ(render(*backend, lookupJob(image, centre))[0], 0.75f);
}

TEST(GlRenderTexture2D, SamplerWithoutATextureIsAUsageErrorNamingIt) {
  auto backend = makeGlBackend({});
  const Image image = distinctTexelImage();
  RenderJob job = lookupJob(image, {0.5f, 0.5f});
  job.textures2D.clear();
  job.textures2D["Other"] = &image;
  try {
    backend->render(job);
    FAIL() << "expected UsageError";
  } catch (const UsageError& error) {
    EXPECT_NE(std::string(error.what()).find("'Tex'"), std::string::npos) << error.what();
  }
}

TEST(GlRenderTexture2D, ImageOfTheWrongSizeIsAUsageError) {
  auto backend = makeGlBackend({});
  Image image = distinctTexelImage();
  image.pixels.resize(12);
  try {
    backend->render(lookupJob(image, {0.5f, 0.5f}));
    FAIL() << "expected UsageError";
  } catch (const UsageError& error) {
    EXPECT_NE(std::string(error.what()).find("4x2"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace snell
