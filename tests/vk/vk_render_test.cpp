// Renders through the public Backend interface with validation on: any
// validation message turns the call that caused it into a SetupError.
#include <gtest/gtest.h>

#include <array>
#include <string>

#include "backends/vk/vk_backend.h"
#include "core/errors.h"
#include "render_geometry.h"
#include "vk_test_support.h"

namespace snell {
namespace {

using Rgba = std::array<float, 4>;

Backend& backend() {
  static std::unique_ptr<Backend> shared = makeVkBackend(BackendOptions{.validation = true});
  return *shared;
}

const char* kPassThrough = R"(#version 140
in vec4 Position;
in vec4 Colour;
out vec4 Shade;
void main() { Shade = Colour; gl_Position = Position; }
)";

const char* kShade = R"(#version 140
in vec4 Shade;
out vec4 FragColor;
void main() { FragColor = Shade; }
)";

ProgramSource program(const char* vertex, const char* fragment) {
  ProgramSource source;
  source.vertex = vertex;
  source.fragment = fragment;
  source.vertexPath = "probes/render.vert";
  source.fragmentPath = "probes/render.frag";
  return source;
}

// Every vertex of `mesh` gets `colour`; the job draws it with the given culling.
RenderJob colouredJob(const vktest::Mesh& mesh, const Rgba& colour, int width, int height) {
  RenderJob job;
  job.program = program(kPassThrough, kShade);
  job.attributes["Position"] = mesh.positions;
  AttributeStream& colours = job.attributes["Colour"] = {"Colour", 4, {}};
  for (std::size_t v = 0; v < mesh.positions.vertexCount(); ++v)
    colours.data.insert(colours.data.end(), colour.begin(), colour.end());
  job.indices = mesh.indices;
  job.width = width;
  job.height = height;
  job.clearColor = {0.5f, 0.25f, 0.125f, 1.0f};
  return job;
}

Rgba pixel(const Image& image, int x, int y) {
  const float* p = image.at(x, y);
  return {p[0], p[1], p[2], p[3]};
}

int countPixels(const Image& image, const Rgba& colour) {
  int count = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) count += pixel(image, x, y) == colour;
  }
  return count;
}

TEST(VkRender, TheTargetIsFloatAndTakesTheColourExactly) {
  // None of these is a multiple of 1/255: an 8-bit target would round them.
  const Rgba paint = {0.1f, 0.2f, 0.3f, 0.7f};
  ProgramSource source =
      program("#version 140\nin vec4 Position;\nvoid main() { gl_Position = Position; }\n",
              "#version 140\nuniform vec4 Paint;\nout vec4 FragColor;\n"
              "void main() { FragColor = Paint; }\n");
  vktest::Mesh mesh;
  vktest::addRectangle(mesh, -1, -1, 1, 1, 0.5f);
  RenderJob job;
  job.program = source;
  job.attributes["Position"] = mesh.positions;
  job.indices = mesh.indices;
  job.uniforms["Paint"] = Value{ValueType::Vec4, {paint.begin(), paint.end()}};
  job.width = 7;  // odd and not square: a swapped or padded row shows up
  job.height = 5;
  job.clearColor = {0.9f, 0.9f, 0.9f, 0.9f};

  const RenderOutcome outcome = backend().render(job);
  ASSERT_TRUE(outcome.compile.ok) << outcome.compile.log;
  ASSERT_EQ(outcome.image.width, 7);
  ASSERT_EQ(outcome.image.height, 5);
  ASSERT_EQ(outcome.image.pixels.size(), 7u * 5u * 4u);
  EXPECT_EQ(countPixels(outcome.image, paint), 7 * 5);
}

TEST(VkRender, AnEmptyDrawGivesTheClearColourExactly) {
  RenderJob job = colouredJob({}, {}, 4, 3);
  job.clearColor = {0.1f, -2.5f, 1e-3f, 65504.0f};
  const RenderOutcome outcome = backend().render(job);
  ASSERT_TRUE(outcome.compile.ok) << outcome.compile.log;
  EXPECT_EQ(countPixels(outcome.image, job.clearColor), 4 * 3);
}

TEST(VkRender, ClipSpaceUpIsRowZeroAndRightIsTheLastColumn) {
  constexpr int kSize = 8;
  const Rgba red = {1, 0, 0, 1};
  vktest::Mesh topHalf;
  // One triangle that covers all of y in [0, 1] and nothing below y = 0.
  vktest::addTriangle(topHalf, {{-1, 0}, {3, 0}, {-1, 4}}, 0.5f);
  const RenderOutcome top = backend().render(colouredJob(topHalf, red, kSize, kSize));
  ASSERT_TRUE(top.compile.ok) << top.compile.log;
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      EXPECT_EQ(pixel(top.image, x, y) == red, y < kSize / 2) << "pixel " << x << ", " << y;
    }
  }

  vktest::Mesh rightHalf;
  vktest::addRectangle(rightHalf, 0, -1, 1, 1, 0.5f);
  const RenderOutcome right = backend().render(colouredJob(rightHalf, red, kSize, kSize));
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      EXPECT_EQ(pixel(right.image, x, y) == red, x >= kSize / 2) << "pixel " << x << ", " << y;
    }
  }
}

TEST(VkRender, TheNearerSurfaceWinsWhicheverIsDrawnFirst) {
  const Rgba nearColour = {0, 1, 0, 1};
  const Rgba farColour = {0, 0, 1, 1};
  for (bool nearFirst : {true, false}) {
    vktest::Mesh mesh;
    const float depths[2] = {nearFirst ? 0.25f : 0.75f, nearFirst ? 0.75f : 0.25f};
    for (float z : depths) vktest::addRectangle(mesh, -1, -1, 1, 1, z);
    RenderJob job = colouredJob(mesh, {}, 4, 4);
    std::vector<float>& colours = job.attributes["Colour"].data;
    colours.clear();
    for (float z : depths) {
      const Rgba& colour = z < 0.5f ? nearColour : farColour;
      for (int v = 0; v < 4; ++v) colours.insert(colours.end(), colour.begin(), colour.end());
    }
    const RenderOutcome outcome = backend().render(job);
    ASSERT_TRUE(outcome.compile.ok) << outcome.compile.log;
    EXPECT_EQ(countPixels(outcome.image, nearColour), 16) << "near drawn first: " << nearFirst;
  }
}

TEST(VkRender, DepthIsClearedToOneAndTestedWithLess) {
  const Rgba red = {1, 0, 0, 1};
  vktest::Mesh justInside;
  vktest::addRectangle(justInside, -1, -1, 1, 1, 0.999f);
  EXPECT_EQ(countPixels(backend().render(colouredJob(justInside, red, 4, 4)).image, red), 16);
  vktest::Mesh atOne;
  vktest::addRectangle(atOne, -1, -1, 1, 1, 1.0f);
  EXPECT_EQ(countPixels(backend().render(colouredJob(atOne, red, 4, 4)).image, red), 0);
}

TEST(VkRender, ClockwiseTrianglesAreCulledAsInOpenGL) {
  const Rgba red = {1, 0, 0, 1};
  const float clockwise[3][2] = {{-1, -1}, {-1, 1}, {1, -1}};
  const float counterClockwise[3][2] = {{-1, -1}, {1, -1}, {-1, 1}};
  vktest::Mesh back, front;
  vktest::addTriangle(back, clockwise, 0.5f);
  vktest::addTriangle(front, counterClockwise, 0.5f);

  RenderJob job = colouredJob(back, red, 8, 8);
  job.cullBackFaces = true;
  EXPECT_EQ(countPixels(backend().render(job).image, red), 0);
  job.cullBackFaces = false;
  const int backDrawn = countPixels(backend().render(job).image, red);
  EXPECT_GT(backDrawn, 20);  // half of 64, less the diagonal's share

  RenderJob frontJob = colouredJob(front, red, 8, 8);
  frontJob.cullBackFaces = true;
  EXPECT_EQ(countPixels(backend().render(frontJob).image, red), backDrawn);
}

TEST(VkRender, CompileErrorGivesOkFalseAndNoImage) {
  RenderJob job = colouredJob({}, {}, 4, 4);
  job.program.fragment =
      "#version 140\nout vec4 FragColor;\nvoid main() { FragColor = missing; }\n";
  const RenderOutcome outcome = backend().render(job);
  EXPECT_FALSE(outcome.compile.ok);
  EXPECT_NE(outcome.compile.log.find("probes/render.frag"), std::string::npos)
      << outcome.compile.log;
  EXPECT_NE(outcome.compile.log.find("missing"), std::string::npos) << outcome.compile.log;
  EXPECT_EQ(outcome.image.width, 0);
  EXPECT_TRUE(outcome.image.pixels.empty());
}

TEST(VkRender, CompatibilityProfileRendersThroughTheLegacyAdapter) {
  vktest::Mesh mesh;
  vktest::addRectangle(mesh, -1, -1, 1, 1, 0.5f);
  RenderJob job = colouredJob(mesh, {0.0f, 1.0f, 0.0f, 1.0f}, 4, 4);
  job.program.profile = Profile::Compatibility;
  const RenderOutcome outcome = backend().render(job);
  ASSERT_TRUE(outcome.compile.ok) << outcome.compile.log;
  EXPECT_EQ(outcome.image.width, 4);
  EXPECT_FALSE(outcome.image.pixels.empty());
}

TEST(VkRender, BadJobsAreUsageErrors) {
  vktest::Mesh mesh;
  vktest::addRectangle(mesh, -1, -1, 1, 1, 0.5f);
  RenderJob noFragment = colouredJob(mesh, {}, 4, 4);
  noFragment.program.fragment.clear();
  EXPECT_THROW(backend().render(noFragment), UsageError);

  RenderJob partTriangle = colouredJob(mesh, {}, 4, 4);
  partTriangle.indices.pop_back();
  EXPECT_THROW(backend().render(partTriangle), UsageError);

  RenderJob pastTheStream = colouredJob(mesh, {}, 4, 4);
  pastTheStream.indices.back() = 4;  // the rectangle has vertices 0 to 3
  EXPECT_THROW(backend().render(pastTheStream), UsageError);

  RenderJob empty = colouredJob(mesh, {}, 0, 4);
  EXPECT_THROW(backend().render(empty), UsageError);

  // The backend is still usable afterwards.
  const RenderOutcome outcome = backend().render(colouredJob(mesh, {0, 1, 0, 1}, 2, 2));
  EXPECT_EQ(countPixels(outcome.image, {0, 1, 0, 1}), 4);
}

}  // namespace
}  // namespace snell
