#pragma once
// Scenes provide the values that manifests bind by semantic ("scene.normal"),
// as Shadertoy provides iResolution. Oracle and backends get the same floats.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/cube_map.h"
#include "core/values.h"

namespace snell {

struct Scene {
  std::string name;
  std::string description;
  UniformMap values;          // "modelview", "modelview_projection", "normal_matrix", ...
  AttributeMap attributes;    // "position" (vec4), "normal" (vec3)
  std::vector<std::string> samplers;  // semantics bound to textures ("environment")
  std::size_t vertexCount = 0;
  // Scenes that draw: a triangle list (counter-clockwise front faces), the
  // image size, and the environment bound to `samplers`.
  std::vector<std::uint32_t> indices;
  int width = 256;
  int height = 256;
  std::shared_ptr<const CubeMap> environment;
  bool draws() const { return !indices.empty(); }
};

std::vector<std::string> sceneNames();
// Throws UsageError naming the known scenes.
Scene makeScene(const std::string& name);

}  // namespace snell
