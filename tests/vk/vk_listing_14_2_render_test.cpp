// Listings 14.1 and 14.2 (Orange Book, Fresnel reflection and refraction)
// rendered as published on the Vulkan backend, validation on.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <set>

#include "backends/vk/vk_backend.h"
#include "render_geometry.h"
#include "vk_test_support.h"

namespace snell {
namespace {

const char* kVertexPath = "shaders/orange-book/14.1-fresnel/fresnel.vert";
const char* kFragmentPath = "shaders/orange-book/14.1-fresnel/fresnel.frag";
constexpr int kSize = 32;
constexpr float kRadius = 0.8f;
const std::array<float, 4> kClear = {0.0f, 0.0f, 0.0f, 0.0f};

ProgramSource listing() {
  ProgramSource program;
  program.vertex = vktest::readSourceFile(kVertexPath);
  program.fragment = vktest::readSourceFile(kFragmentPath);
  program.vertexPath = kVertexPath;
  program.fragmentPath = kFragmentPath;
  return program;
}

std::vector<float> identity(int size) {
  std::vector<float> m(static_cast<std::size_t>(size * size), 0.0f);
  for (int i = 0; i < size; ++i) m[static_cast<std::size_t>(i * size + i)] = 1.0f;
  return m;
}

// The eye at the origin looks down -z at a sphere centred at (0, 0, -3);
// the projection is orthographic and maps the sphere's depth range,
// z_eye in [-3.8, -2.2], to NDC z in [0.1, 0.9], the near side lowest.
UniformMap sceneUniforms() {
  std::vector<float> modelView = identity(4);
  modelView[14] = -3.0f;
  std::vector<float> modelViewProjection = identity(4);
  modelViewProjection[10] = -0.5f;
  modelViewProjection[14] = 0.5f;
  return {{"MVMatrix", {ValueType::Mat4, modelView}},
          {"MVPMatrix", {ValueType::Mat4, modelViewProjection}},
          {"NormalMatrix", {ValueType::Mat3, identity(3)}},
          {"TextureMatrix", {ValueType::Mat4, identity(4)}}};
}

CubeMap environment() {
  std::mt19937 random(11);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  CubeMap cube;
  cube.size = 4;
  cube.filter = CubeFilter::Linear;
  for (std::vector<float>& face : cube.faces) {
    face.resize(static_cast<std::size_t>(cube.size * cube.size * 4));
    for (float& value : face) value = unit(random);
  }
  return cube;
}

struct Scene {
  vktest::Mesh mesh = vktest::sphere(kRadius, 16, 32);
  CubeMap cube = environment();

  RenderJob renderJob() const {
    RenderJob job;
    job.program = listing();
    job.uniforms = sceneUniforms();
    job.attributes["MCvertex"] = {"MCvertex", 4, mesh.positions.data};
    job.attributes["MCnormal"] = {"MCnormal", 3, mesh.normals.data};
    job.indices = mesh.indices;
    job.cubeMaps["Cubemap"] = &cube;
    job.width = kSize;
    job.height = kSize;
    job.clearColor = kClear;
    return job;
  }

  CaptureJob captureJob() const {
    CaptureJob job;
    job.program = listing();
    job.uniforms = sceneUniforms();
    job.attributes["MCvertex"] = {"MCvertex", 4, mesh.positions.data};
    job.attributes["MCnormal"] = {"MCnormal", 3, mesh.normals.data};
    job.varyings = {"Reflect", "Refract", "Ratio"};
    job.vertexCount = mesh.positions.vertexCount();
    return job;
  }
};

bool isClear(const float* p) { return std::equal(p, p + 4, kClear.begin()); }

TEST(VkListing14_2, RendersTheSphereWithColoursFromTheEnvironment) {
  auto backend = makeVkBackend(BackendOptions{.validation = true});
  const Scene scene;
  const RenderOutcome outcome = backend->render(scene.renderJob());
  ASSERT_TRUE(outcome.compile.ok) << outcome.compile.log;
  ASSERT_EQ(outcome.image.width, kSize);
  ASSERT_EQ(outcome.image.height, kSize);

  // Every colour the listing makes is a mix of linear-filtered texels, so
  // it lies within the environment's range in each channel; pow() and mix()
  // may stray by a few ULPs.
  std::array<float, 3> low = {1, 1, 1}, high = {0, 0, 0};
  for (const std::vector<float>& face : scene.cube.faces) {
    for (std::size_t i = 0; i < face.size(); ++i) {
      if (i % 4 == 3) continue;
      low[i % 4] = std::min(low[i % 4], face[i]);
      high[i % 4] = std::max(high[i % 4], face[i]);
    }
  }
  std::set<std::array<float, 3>> colours;
  int inside = 0;
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      const double ndcX = (x + 0.5) * 2 / kSize - 1, ndcY = 1 - (y + 0.5) * 2 / kSize;
      const double r = std::hypot(ndcX, ndcY);
      const float* p = outcome.image.at(x, y);
      // The mesh is inscribed in the sphere: nothing beyond its radius, and
      // with 32 segments it reaches past 0.78 everywhere.
      if (r > kRadius) {
        EXPECT_TRUE(isClear(p)) << "pixel " << x << ", " << y << " is outside the sphere";
        continue;
      }
      if (r > 0.75) continue;
      ++inside;
      ASSERT_FALSE(isClear(p)) << "pixel " << x << ", " << y << " is inside the sphere";
      EXPECT_EQ(p[3], 1.0f);
      for (int c = 0; c < 3; ++c) {
        EXPECT_GE(p[c], low[c] - 1e-5f) << "pixel " << x << ", " << y;
        EXPECT_LE(p[c], high[c] + 1e-5f) << "pixel " << x << ", " << y;
      }
      colours.insert({p[0], p[1], p[2]});
    }
  }
  EXPECT_GT(inside, 400);  // pi * 0.75^2 / 4 of 1024 pixels is about 450
  EXPECT_GT(colours.size(), 50u) << "reflections and refractions should vary across the sphere";
}

TEST(VkListing14_2, InterleavedCapturesAndRendersRepeatExactly) {
  auto backend = makeVkBackend(BackendOptions{.validation = true});
  const Scene scene;
  const CaptureJob capture = scene.captureJob();
  const RenderJob render = scene.renderJob();
  std::vector<CapturedVarying> firstCapture;
  std::vector<float> firstImage;
  for (int call = 0; call < 20; ++call) {
    if (call % 2 == 0) {
      const CaptureOutcome outcome = backend->captureVertexOutputs(capture);
      ASSERT_TRUE(outcome.compile.ok) << outcome.compile.log;
      ASSERT_EQ(outcome.varyings.size(), 3u);
      if (call == 0) firstCapture = outcome.varyings;
      for (std::size_t v = 0; v < 3; ++v) {
        ASSERT_EQ(outcome.varyings[v].data, firstCapture[v].data) << "call " << call;
      }
    } else {
      const RenderOutcome outcome = backend->render(render);
      ASSERT_TRUE(outcome.compile.ok) << outcome.compile.log;
      if (call == 1) firstImage = outcome.image.pixels;
      ASSERT_EQ(outcome.image.pixels, firstImage) << "call " << call;
    }
  }
  EXPECT_EQ(firstCapture[2].data.size(), scene.mesh.positions.vertexCount());
  EXPECT_TRUE(std::any_of(firstImage.begin(), firstImage.end(), [](float v) { return v != 0; }));
}

}  // namespace
}  // namespace snell
