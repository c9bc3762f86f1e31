#pragma once
// A scene as data (scenes/<name>.toml): the shape and its tessellation, the
// model turn, the camera, the environment and its transform, the image size.
#include <array>
#include <filesystem>
#include <string>
#include <vector>

namespace snell {

struct SceneFile {
  std::filesystem::path path;
  std::string name;  // the file name without .toml
  std::string description;
  std::string shape;  // "sphere", "torus", "sweep" or "fullscreen"
  // Shape parameters: sphere stacks/slices; torus major_radius, minor_radius,
  // rings, sides; sweep count, seed. Absent ones stay 0.
  int stacks = 0, slices = 0, rings = 0, sides = 0, count = 0;
  long long seed = 0;
  double majorRadius = 0, minorRadius = 0;
  std::array<double, 3> modelAxis{0, 1, 0};
  double modelDegrees = 0;
  // [model] scale: applied before the turn. Unequal factors make
  // NormalMatrix (the inverse transpose) give normals that are not unit
  // length, so a listing's normalize() calls matter.
  std::array<double, 3> modelScale{1, 1, 1};
  std::array<double, 3> eye{}, center{0, 0, -1}, up{0, 1, 0};
  double fovyDegrees = 45, zNear = 0.5, zFar = 10;
  int environmentSize = 128;
  std::array<double, 3> environmentAxis{0, 1, 0}, environmentTranslation{};
  double environmentDegrees = 0;
  int width = 0, height = 0;  // 0: the scene draws nothing
};

// Throws UsageError "FILE:LINE: what; what to do".
SceneFile loadSceneFile(const std::filesystem::path& path);

// Where scenes are looked up: the shaders folder's own scenes/ first (a
// user's listings may bring theirs), then the repository's scenes/.
std::vector<std::filesystem::path> sceneSearchPath(const std::filesystem::path& shadersDir);
std::filesystem::path builtInScenesDir();

}  // namespace snell
