#pragma once
// Scenes provide the values that manifests bind by semantic ("scene.normal"),
// as Shadertoy provides iResolution. Oracle and backends get the same floats.
// Each scene is described as data in scenes/<name>.toml (core/scene_file.h).
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "core/cube_map.h"
#include "core/image.h"
#include "core/values.h"

namespace snell {

struct Scene {
  std::string name;
  std::string description;
  // "model", "view", "projection", their products "modelview",
  // "view_projection", "modelview_projection", the normal matrices
  // "normal_matrix" (eye space) and "model_normal_matrix" (world space),
  // "eye_position" (world space), ... (the table in shaders/README.md).
  UniformMap values;
  // "position" (vec4), "normal" (vec3), "tangent" (vec3); on the sphere and
  // the torus also "texcoord" (vec2, the grid's (u, v) in [0, 1]), which the
  // sweep and the full-screen pass have no surface to give, so they omit it.
  AttributeMap attributes;
  std::vector<std::string> samplers;  // semantics bound to textures ("environment", "decal")
  std::size_t vertexCount = 0;
  // Scenes that draw: a triangle list (counter-clockwise front faces), the
  // image size, and the environment (samplerCube) and decal (sampler2D)
  // bound to `samplers` (core/environment.h, core/decal.h).
  std::vector<std::uint32_t> indices;
  int width = 0;
  int height = 0;
  std::shared_ptr<const CubeMap> environment;
  std::shared_ptr<const Image> decal;
  bool draws() const { return !indices.empty(); }
};

// The scene names found on the search path (file names without .toml).
std::vector<std::string> sceneNames(const std::vector<std::filesystem::path>& searchPath);

// The first scenes/<name>.toml on the search path, built; throws UsageError
// naming the known scenes when there is none, or the file and line of a
// broken one.
Scene makeScene(const std::string& name, const std::vector<std::filesystem::path>& searchPath);
// The repository's own scenes.
Scene makeScene(const std::string& name);

// A scene built from its file as read (or changed in memory: `snell bench`
// draws the sphere at other tessellations this way).
struct SceneFile;
Scene buildScene(const SceneFile& file);

}  // namespace snell
