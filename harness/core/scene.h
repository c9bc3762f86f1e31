#pragma once
// Scenes provide the values that manifests bind by semantic ("scene.normal"),
// as Shadertoy provides iResolution. Oracle and backends get the same floats.
#include <string>
#include <vector>

#include "core/values.h"

namespace snell {

struct Scene {
  std::string name;
  std::string description;
  UniformMap values;          // "modelview", "modelview_projection", "normal_matrix", ...
  AttributeMap attributes;    // "position" (vec4), "normal" (vec3)
  std::vector<std::string> samplers;  // semantics bound to textures ("environment")
  std::size_t vertexCount = 0;
};

std::vector<std::string> sceneNames();
// Throws UsageError naming the known scenes.
Scene makeScene(const std::string& name);

}  // namespace snell
