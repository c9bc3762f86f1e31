#include "core/scene_file.h"

#include <fmt/format.h>
#include <toml++/toml.h>

#include "core/errors.h"
#include "core/toml_keys.h"

namespace snell {
namespace {

namespace fs = std::filesystem;

class SceneReader {
 public:
  explicit SceneReader(fs::path path) : path_(std::move(path)) {}

  [[noreturn]] void fail(const toml::node* node, const std::string& what) const {
    const int line = node ? static_cast<int>(node->source().begin.line) : 1;
    throw UsageError(fmt::format("{}:{}: {}", path_.string(), line, what));
  }

  const toml::table* table(const toml::table& root, std::string_view key, bool required) const {
    const toml::node* node = root.get(key);
    if (!node) {
      if (required) fail(nullptr, fmt::format("missing table [{}]", key));
      return nullptr;
    }
    if (!node->is_table()) fail(node, fmt::format("`{}` must be a table", key));
    return node->as_table();
  }

  double number(const toml::table& t, std::string_view key, double fallback, bool required) const {
    const toml::node* node = t.get(key);
    if (!node) {
      if (required) fail(&t, fmt::format("missing `{}`", key));
      return fallback;
    }
    if (!node->is_floating_point() && !node->is_integer())
      fail(node, fmt::format("`{}` must be a number", key));
    return *node->value<double>();
  }

  int positive(const toml::table& t, std::string_view key) const {
    const double x = number(t, key, 0, true);
    if (x < 1 || x != static_cast<int>(x))
      fail(t.get(key), fmt::format("`{}` must be a whole number >= 1", key));
    return static_cast<int>(x);
  }

  std::array<double, 3> vec3(const toml::table& t, std::string_view key,
                             std::array<double, 3> fallback) const {
    const toml::node* node = t.get(key);
    if (!node) return fallback;
    const toml::array* a = node->as_array();
    if (!a || a->size() != 3) fail(node, fmt::format("`{}` must be an array of 3 numbers", key));
    std::array<double, 3> out{};
    for (std::size_t k = 0; k < 3; ++k) {
      const toml::node& e = *a->get(k);
      if (!e.is_floating_point() && !e.is_integer())
        fail(node, fmt::format("`{}` must hold numbers", key));
      out[k] = *e.value<double>();
    }
    return out;
  }

  SceneFile read() const {
    toml::table root;
    try {
      root = toml::parse_file(path_.string());
    } catch (const toml::parse_error& error) {
      throw UsageError(fmt::format("{}:{}: not valid TOML: {}", path_.string(),
                                   error.source().begin.line, error.description()));
    }
    rejectUnknownKeys(root, {"description", "geometry", "model", "camera", "environment", "image"},
                      path_, "the scene");
    SceneFile s;
    s.path = path_;
    s.name = path_.stem().string();
    if (const toml::node* d = root.get("description")) {
      if (!d->is_string()) fail(d, "`description` must be a string");
      s.description = std::string(*d->value<std::string>());
    }
    const toml::table& geometry = *table(root, "geometry", true);
    const toml::node* shape = geometry.get("shape");
    if (!shape || !shape->is_string())
      fail(&geometry,
           "`geometry.shape` must be \"sphere\", \"torus\", \"sweep\" or \"fullscreen\"");
    s.shape = std::string(*shape->value<std::string>());
    if (s.shape == "sphere")
      rejectUnknownKeys(geometry, {"shape", "stacks", "slices"}, path_, "[geometry] of a sphere");
    if (s.shape == "torus")
      rejectUnknownKeys(geometry, {"shape", "major_radius", "minor_radius", "rings", "sides"},
                        path_, "[geometry] of a torus");
    if (s.shape == "sweep")
      rejectUnknownKeys(geometry, {"shape", "count", "seed"}, path_, "[geometry] of a sweep");
    if (s.shape == "fullscreen")
      rejectUnknownKeys(geometry, {"shape"}, path_, "[geometry] of a full-screen pass");
    if (s.shape == "sphere") {
      s.stacks = positive(geometry, "stacks");
      s.slices = positive(geometry, "slices");
    } else if (s.shape == "torus") {
      s.majorRadius = number(geometry, "major_radius", 0, true);
      s.minorRadius = number(geometry, "minor_radius", 0, true);
      if (!(s.minorRadius > 0 && s.minorRadius < s.majorRadius))
        fail(&geometry, "a torus needs 0 < minor_radius < major_radius");
      s.rings = positive(geometry, "rings");
      s.sides = positive(geometry, "sides");
    } else if (s.shape == "sweep") {
      s.count = positive(geometry, "count");
      s.seed = static_cast<long long>(number(geometry, "seed", 1, false));
    } else if (s.shape != "fullscreen") {
      fail(shape,
           fmt::format("unknown shape `{}`; use sphere, torus, sweep or fullscreen", s.shape));
    }
    if (const toml::table* model = table(root, "model", false)) {
      rejectUnknownKeys(*model, {"rotation_axis", "rotation_degrees", "scale"}, path_, "[model]");
      s.modelAxis = vec3(*model, "rotation_axis", s.modelAxis);
      s.modelDegrees = number(*model, "rotation_degrees", 0, false);
      s.modelScale = vec3(*model, "scale", s.modelScale);
      for (double factor : s.modelScale)
        if (!(factor > 0))
          fail(model->get("scale"),
               "`scale` must hold three numbers > 0 (a mirror or a flat "
               "model turns faces around)");
    }
    const toml::table& camera = *table(root, "camera", true);
    rejectUnknownKeys(camera, {"eye", "center", "up", "fovy_degrees", "near", "far"}, path_,
                      "[camera]");
    s.eye = vec3(camera, "eye", s.eye);
    s.center = vec3(camera, "center", s.center);
    s.up = vec3(camera, "up", s.up);
    s.fovyDegrees = number(camera, "fovy_degrees", s.fovyDegrees, false);
    s.zNear = number(camera, "near", s.zNear, false);
    s.zFar = number(camera, "far", s.zFar, false);
    if (!(s.zNear > 0 && s.zFar > s.zNear)) fail(&camera, "the camera needs 0 < near < far");
    if (const toml::table* env = table(root, "environment", false)) {
      rejectUnknownKeys(*env, {"size", "rotation_axis", "rotation_degrees", "translation"}, path_,
                        "[environment]");
      s.environmentSize = static_cast<int>(number(*env, "size", s.environmentSize, false));
      s.environmentAxis = vec3(*env, "rotation_axis", s.environmentAxis);
      s.environmentDegrees = number(*env, "rotation_degrees", 0, false);
      s.environmentTranslation = vec3(*env, "translation", s.environmentTranslation);
    }
    if (const toml::table* image = table(root, "image", false)) {
      if (s.shape == "sweep") fail(image, "a sweep draws nothing: remove [image]");
      rejectUnknownKeys(*image, {"width", "height"}, path_, "[image]");
      s.width = positive(*image, "width");
      s.height = positive(*image, "height");
    } else if (s.shape != "sweep") {
      fail(nullptr, "a scene that draws needs [image] width and height");
    }
    return s;
  }

 private:
  fs::path path_;
};

}  // namespace

SceneFile loadSceneFile(const fs::path& path) { return SceneReader(path).read(); }

fs::path builtInScenesDir() { return SNELL_SOURCE_ROOT "/scenes"; }

std::vector<fs::path> sceneSearchPath(const fs::path& shadersDir) {
  return {shadersDir / "scenes", builtInScenesDir()};
}

}  // namespace snell
