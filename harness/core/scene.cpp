#include "core/scene.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <set>

#include "core/camera_math.h"
#include "core/decal.h"
#include "core/environment.h"
#include "core/errors.h"
#include "core/scene_file.h"

namespace snell {
namespace {

namespace fs = std::filesystem;
constexpr double kPi = std::numbers::pi;

double radians(double degrees) { return degrees * kPi / 180; }

void addCameraValues(Scene& scene, const SceneFile& file) {
  Mat4d scale = identity4();
  for (int c = 0; c < 3; ++c) scale[c * 4 + c] = file.modelScale[c];
  const Mat4d model = multiply(rotation({file.modelAxis[0], file.modelAxis[1], file.modelAxis[2]},
                                        radians(file.modelDegrees)),
                               scale);
  const Vec3d eye = {file.eye[0], file.eye[1], file.eye[2]};
  const Mat4d view = lookAt(eye, {file.center[0], file.center[1], file.center[2]},
                            {file.up[0], file.up[1], file.up[2]});
  const Mat4d projection = perspective(radians(file.fovyDegrees), 1.0, file.zNear, file.zFar);
  const Mat4d modelview = multiply(view, model);
  // Each product is formed in double and rounded to float once, so a shader
  // that multiplies the separate matrices itself (LearnOpenGL's
  // projection * view * model) and one given the product see values that
  // differ only by the shader's own rounding.
  scene.values["model"] = toMat4Value(model);
  scene.values["view"] = toMat4Value(view);
  scene.values["eye_position"] =
      Value{ValueType::Vec3,
            {static_cast<float>(eye[0]), static_cast<float>(eye[1]), static_cast<float>(eye[2])}};
  scene.values["modelview"] = toMat4Value(modelview);
  scene.values["projection"] = toMat4Value(projection);
  scene.values["view_projection"] = toMat4Value(multiply(projection, view));
  scene.values["modelview_projection"] = toMat4Value(multiply(projection, modelview));
  // Normals to eye space (gl_NormalMatrix, three.js's normalMatrix) and to
  // world space (LearnOpenGL's mat3(transpose(inverse(model)))).
  scene.values["normal_matrix"] = normalMatrixValue(modelview);
  scene.values["model_normal_matrix"] = normalMatrixValue(model);
  const Mat4d environment =
      multiply(translation({file.environmentTranslation[0], file.environmentTranslation[1],
                            file.environmentTranslation[2]}),
               rotation({file.environmentAxis[0], file.environmentAxis[1], file.environmentAxis[2]},
                        radians(file.environmentDegrees)));
  scene.values["texture_matrix"] = toMat4Value(environment);
  scene.samplers = {"environment", "decal"};
}

void addVertex(AttributeStream& position, AttributeStream& normal, const Vec3d& p, const Vec3d& n) {
  for (double c : p) position.data.push_back(static_cast<float>(c));
  position.data.push_back(1.0f);
  for (double c : n) normal.data.push_back(static_cast<float>(c));
}

// The per-vertex tangent: a unit vector perpendicular to the normal.
void addTangent(AttributeStream& tangent, const Vec3d& t) {
  for (double c : t) tangent.data.push_back(static_cast<float>(c));
}

// The grid's (u, v) in [0, 1]: the seam column and the last row repeat the
// first at u = 1 and v = 1, so no triangle's coordinates wrap.
void addTexcoord(AttributeStream& texcoord, double u, double v) {
  texcoord.data.push_back(static_cast<float>(u));
  texcoord.data.push_back(static_cast<float>(v));
}

// A (rows + 1) x (columns + 1) vertex grid wrapped onto a surface: two
// counter-clockwise triangles per cell, degenerate ones (at a sphere's
// poles) left out.
void gridTriangles(Scene& scene, int rows, int columns, bool skipFirstRow, bool skipLastRow) {
  const auto vertex = [&](int row, int column) {
    return static_cast<std::uint32_t>(row * (columns + 1) + column);
  };
  for (int row = 0; row < rows; ++row)
    for (int column = 0; column < columns; ++column) {
      if (!(skipFirstRow && row == 0))
        scene.indices.insert(scene.indices.end(), {vertex(row, column), vertex(row, column + 1),
                                                   vertex(row + 1, column)});
      if (!(skipLastRow && row + 1 == rows))
        scene.indices.insert(
            scene.indices.end(),
            {vertex(row, column + 1), vertex(row + 1, column + 1), vertex(row + 1, column)});
    }
}

void sphere(Scene& scene, const SceneFile& file) {
  AttributeStream position{"position", 4, {}}, normal{"normal", 3, {}}, tangent{"tangent", 3, {}};
  AttributeStream texcoord{"texcoord", 2, {}};
  for (int stack = 0; stack <= file.stacks; ++stack) {
    const double theta = kPi * stack / file.stacks;
    for (int slice = 0; slice <= file.slices; ++slice) {
      const double phi = 2 * kPi * slice / file.slices;
      const Vec3d n = {std::sin(theta) * std::cos(phi), std::cos(theta),
                       std::sin(theta) * std::sin(phi)};
      addVertex(position, normal, n, n);
      // d/dphi, normalised: along the parallel, defined at the poles too.
      addTangent(tangent, {-std::sin(phi), 0.0, std::cos(phi)});
      addTexcoord(texcoord, static_cast<double>(slice) / file.slices,
                  static_cast<double>(stack) / file.stacks);
    }
  }
  gridTriangles(scene, file.stacks, file.slices, true, true);
  scene.attributes["position"] = std::move(position);
  scene.attributes["normal"] = std::move(normal);
  scene.attributes["tangent"] = std::move(tangent);
  scene.attributes["texcoord"] = std::move(texcoord);
}

void torus(Scene& scene, const SceneFile& file) {
  AttributeStream position{"position", 4, {}}, normal{"normal", 3, {}}, tangent{"tangent", 3, {}};
  AttributeStream texcoord{"texcoord", 2, {}};
  for (int ring = 0; ring <= file.rings; ++ring) {
    const double u = 2 * kPi * ring / file.rings;
    for (int side = 0; side <= file.sides; ++side) {
      // Rings run around the y axis, sides around the tube, in the order that
      // makes the grid's triangles face outward (tests/core/scene_test.cpp).
      const double v = 2 * kPi * side / file.sides;
      const Vec3d n = {std::cos(v) * std::cos(u), std::sin(v), std::cos(v) * std::sin(u)};
      const Vec3d p = {(file.majorRadius + file.minorRadius * std::cos(v)) * std::cos(u),
                       file.minorRadius * std::sin(v),
                       (file.majorRadius + file.minorRadius * std::cos(v)) * std::sin(u)};
      addVertex(position, normal, p, n);
      // Along the ring (d/du, normalised), perpendicular to n.
      addTangent(tangent, {-std::sin(u), 0.0, std::cos(u)});
      addTexcoord(texcoord, static_cast<double>(ring) / file.rings,
                  static_cast<double>(side) / file.sides);
    }
  }
  gridTriangles(scene, file.rings, file.sides, false, false);
  scene.attributes["position"] = std::move(position);
  scene.attributes["normal"] = std::move(normal);
  scene.attributes["tangent"] = std::move(tangent);
  scene.attributes["texcoord"] = std::move(texcoord);
}

void sweep(Scene& scene, const SceneFile& file) {
  std::mt19937_64 random(static_cast<std::uint64_t>(file.seed));  // raw output: the same everywhere
  auto uniform = [&] { return static_cast<double>(random() >> 11) * 0x1.0p-53; };
  AttributeStream position{"position", 4, {}}, normal{"normal", 3, {}}, tangent{"tangent", 3, {}};
  const int count = file.count;
  for (int k = 0; k < count; ++k) {
    const double t = count > 1 ? static_cast<double>(k) / (count - 1) : 0.0;
    double angle;  // incidence angle in degrees
    if (k < count / 2)
      angle = 90.0 * (2 * t);  // 0..90
    else if (k < 3 * count / 4)
      angle = 90.0 * (1 - std::pow(10.0, -1 - 6 * (4 * t - 2)));  // to grazing
    else
      angle = 90.0 + 10.0 * std::pow(10.0, -5 * (4 * t - 3));  // just past
    // View direction within 30 degrees of -z, at a distance of 2 to 6.
    const double polar = radians(30.0) * std::sqrt(uniform()), azimuth = 2 * kPi * uniform();
    const Vec3d d = {std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth),
                     -std::cos(polar)};
    const double distance = 2 + 4 * uniform();
    // The normal is -d turned by `angle` about an axis perpendicular to d.
    const Vec3d helper = std::abs(d[0]) < 0.9 ? Vec3d{1, 0, 0} : Vec3d{0, 1, 0};
    const Vec3d u = normalized(cross(d, helper)), w = cross(d, u);
    const double spin = 2 * kPi * uniform(), a = radians(angle);
    Vec3d n;
    for (int c = 0; c < 3; ++c)
      n[c] = -d[c] * std::cos(a) + (u[c] * std::cos(spin) + w[c] * std::sin(spin)) * std::sin(a);
    addVertex(position, normal, {distance * d[0], distance * d[1], distance * d[2]}, n);
    // Any unit vector perpendicular to n (no random draw: the sweep's
    // samples stay as they were).
    const Vec3d away = std::abs(n[0]) < 0.9 ? Vec3d{1, 0, 0} : Vec3d{0, 1, 0};
    addTangent(tangent, normalized(cross(n, away)));
  }
  scene.attributes["position"] = std::move(position);
  scene.attributes["normal"] = std::move(normal);
  scene.attributes["tangent"] = std::move(tangent);
}

// One triangle over the whole viewport, straight in clip space, as
// Shadertoy draws: every pixel runs the fragment shader once, and no edge
// crosses the image.
void fullscreen(Scene& scene) {
  AttributeStream position{"position", 4, {-1, -1, 0.5f, 1, 3, -1, 0.5f, 1, -1, 3, 0.5f, 1}};
  AttributeStream normal{"normal", 3, {0, 0, 1, 0, 0, 1, 0, 0, 1}};
  AttributeStream tangent{"tangent", 3, {1, 0, 0, 1, 0, 0, 1, 0, 0}};
  scene.indices = {0, 1, 2};
  scene.attributes["position"] = std::move(position);
  scene.attributes["normal"] = std::move(normal);
  scene.attributes["tangent"] = std::move(tangent);
}

Scene build(const SceneFile& file) {
  Scene scene;
  scene.name = file.name;
  scene.description = file.description;
  if (file.shape == "sphere")
    sphere(scene, file);
  else if (file.shape == "torus")
    torus(scene, file);
  else if (file.shape == "fullscreen")
    fullscreen(scene);
  else
    sweep(scene, file);
  scene.vertexCount = scene.attributes.at("position").vertexCount();
  addCameraValues(scene, file);
  if (!scene.indices.empty()) {
    scene.width = file.width;
    scene.height = file.height;
    scene.environment = sharedEnvironment(file.environmentSize);
    scene.decal = std::make_shared<const Image>(makeDecal());
    // Shadertoy's iResolution: the viewport in pixels, and a pixel aspect of 1.
    scene.values["resolution"] = Value{
        ValueType::Vec3, {static_cast<float>(file.width), static_cast<float>(file.height), 1.0f}};
  }
  return scene;
}

}  // namespace

std::vector<std::string> sceneNames(const std::vector<fs::path>& searchPath) {
  std::set<std::string> names;
  for (const fs::path& dir : searchPath)
    if (fs::is_directory(dir))
      for (const auto& entry : fs::directory_iterator(dir))
        if (entry.path().extension() == ".toml") names.insert(entry.path().stem().string());
  return {names.begin(), names.end()};
}

Scene makeScene(const std::string& name, const std::vector<fs::path>& searchPath) {
  for (const fs::path& dir : searchPath) {
    const fs::path file = dir / (name + ".toml");
    if (fs::is_regular_file(file)) return build(loadSceneFile(file));
  }
  throw UsageError(fmt::format("unknown scene `{}`; known scenes: {}", name,
                               fmt::join(sceneNames(searchPath), ", ")));
}

Scene makeScene(const std::string& name) { return makeScene(name, {builtInScenesDir()}); }

Scene buildScene(const SceneFile& file) { return build(file); }

}  // namespace snell
