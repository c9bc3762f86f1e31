// A LearnOpenGL-style vertex shader (vec3 aPos, separate model, view and
// projection) bound through a manifest to the scene's semantics runs as
// written: aPos gets x, y, z of scene.position, and the world position and
// clip position it computes match the scene's matrices. On every
// registered API: the same shader, the same checks.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "backends/backend.h"
#include "core/case.h"
#include "core/manifest.h"

namespace snell {
namespace {

namespace fs = std::filesystem;

const CapturedVarying& varyingNamed(const CaptureOutcome& outcome, const std::string& name) {
  for (const CapturedVarying& v : outcome.varyings)
    if (v.name == name) return v;
  throw std::runtime_error("no captured varying " + name);
}

constexpr const char* kVertex = R"(#version 330 core
layout (location = 0) in vec3 aPos;
layout (location = 1) in vec3 aNormal;
out vec3 Raw;
out vec3 Position;
out vec4 Clip;
out vec3 Normal;
uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;
uniform mat3 worldNormalMatrix;
void main() {
  Raw = aPos;
  Position = vec3(model * vec4(aPos, 1.0));
  Clip = projection * view * vec4(Position, 1.0);
  Normal = worldNormalMatrix * aNormal;
  gl_Position = Clip;
}
)";

constexpr const char* kManifest = R"(id = "test/learnopengl-vertex"
title = "t"
source = { file = "f.txt", where = "here" }
stages = { vertex = "a.vert" }
[inputs]
aPos = "scene.position"
aNormal = "scene.normal"
[uniforms]
model = "scene.model"
view = "scene.view"
projection = "scene.projection"
worldNormalMatrix = "scene.model_normal_matrix"
[capture]
vertex = ["Raw", "Position", "Clip", "Normal"]
[[case]]
scene = "sphere"
)";

class ApiSceneConventions : public ::testing::TestWithParam<std::string> {};

TEST_P(ApiSceneConventions, Vec3PositionAndSeparateMatricesRunAsWritten) {
  const fs::path dir = fs::temp_directory_path() / ("snell-scene-conventions-" + GetParam());
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "a.vert") << kVertex;
  std::ofstream(dir / "manifest.toml") << kManifest;
  const Manifest manifest = loadManifest(dir / "manifest.toml");
  const Scene scene = makeScene("sphere");
  const ResolvedBindings bindings = resolveBindings(manifest, scene);
  CaptureJob job{loadProgram(manifest), bindings.uniforms, bindings.attributes,
                 manifest.captureVertex, bindings.vertexCount};
  const CaptureOutcome outcome =
      makeBackend(GetParam(), BackendOptions{.validation = true})->captureVertexOutputs(job);
  fs::remove_all(dir);
  ASSERT_TRUE(outcome.compile.ok) << outcome.compile.log;

  const std::vector<float>& position = scene.attributes.at("position").data;
  const std::vector<float>& normal = scene.attributes.at("normal").data;
  const auto matrix = [&](const char* name) { return scene.values.at(name).data; };
  const std::vector<float> model = matrix("model"), mvp = matrix("modelview_projection");
  const std::vector<float> normalMatrix = matrix("model_normal_matrix");
  const CapturedVarying& raw = varyingNamed(outcome, "Raw");
  const CapturedVarying& world = varyingNamed(outcome, "Position");
  const CapturedVarying& clip = varyingNamed(outcome, "Clip");
  const CapturedVarying& worldNormal = varyingNamed(outcome, "Normal");
  ASSERT_EQ(raw.data.size(), scene.vertexCount * 3);
  for (std::size_t v = 0; v < scene.vertexCount; ++v) {
    const float* p = &position[v * 4];
    for (int r = 0; r < 3; ++r) ASSERT_EQ(raw.data[v * 3 + r], p[r]) << "vertex " << v;
    // Reference transforms in double from the same floats; the shader's
    // float arithmetic stays within a few ulps of a unit-sized result.
    for (int r = 0; r < 4; ++r) {
      double w = 0, c = 0;
      for (int k = 0; k < 4; ++k) {
        w += double(model[k * 4 + r]) * p[k];
        c += double(mvp[k * 4 + r]) * p[k];
      }
      if (r < 3) {
        ASSERT_NEAR(world.data[v * 3 + r], w, 1e-5) << "vertex " << v;
      }
      ASSERT_NEAR(clip.data[v * 4 + r], c, 1e-4 * std::max(1.0, std::abs(c))) << "vertex " << v;
    }
    for (int r = 0; r < 3; ++r) {
      double n = 0;
      for (int k = 0; k < 3; ++k) n += double(normalMatrix[k * 3 + r]) * normal[v * 3 + k];
      ASSERT_NEAR(worldNormal.data[v * 3 + r], n, 1e-5) << "vertex " << v;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Apis, ApiSceneConventions, ::testing::Values("gl", "vk"));

}  // namespace
}  // namespace snell
