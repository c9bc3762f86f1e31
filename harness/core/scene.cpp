#include "core/scene.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <numbers>
#include <random>

#include "core/camera_math.h"
#include "core/environment.h"
#include "core/errors.h"

namespace snell {
namespace {

constexpr double kPi = std::numbers::pi;

// The environment is rotated and moved independently of the geometry, as the
// Orange Book's application does: the translation makes the listing's
// vec4(Refract, 1.0) matter.
Mat4d environmentTransform() {
  return multiply(translation({0.15, -0.1, 0.2}), rotation({1.0, 2.0, 0.5}, 35.0 * kPi / 180));
}

void addCameraValues(Scene& scene, const Mat4d& model, const Mat4d& view, const Vec3d& eye,
                     const Mat4d& projection) {
  const Mat4d modelview = multiply(view, model);
  scene.values["model"] = toMat4Value(model);
  scene.values["eye_position"] = Value{ValueType::Vec3, {static_cast<float>(eye[0]),
                                                         static_cast<float>(eye[1]),
                                                         static_cast<float>(eye[2])}};
  scene.values["modelview"] = toMat4Value(modelview);
  scene.values["modelview_projection"] = toMat4Value(multiply(projection, modelview));
  scene.values["normal_matrix"] = normalMatrixValue(modelview);
  scene.values["texture_matrix"] = toMat4Value(environmentTransform());
  scene.samplers = {"environment"};
}

// A unit sphere, tessellated by latitude and longitude, turned a little and
// seen through a perspective camera: every incidence angle from normal to
// grazing appears, and past the silhouette the back faces too.
Scene sphere() {
  Scene scene;
  scene.name = "sphere";
  scene.description = "unit sphere, 48 x 96 tessellation, perspective camera";
  constexpr int kStacks = 48, kSlices = 96;
  AttributeStream position{"position", 4, {}}, normal{"normal", 3, {}};
  for (int stack = 0; stack <= kStacks; ++stack) {
    const double theta = kPi * stack / kStacks;
    for (int slice = 0; slice <= kSlices; ++slice) {
      const double phi = 2 * kPi * slice / kSlices;
      const double n[3] = {std::sin(theta) * std::cos(phi), std::cos(theta),
                           std::sin(theta) * std::sin(phi)};
      for (double c : n) position.data.push_back(static_cast<float>(c));
      position.data.push_back(1.0f);
      for (double c : n) normal.data.push_back(static_cast<float>(c));
    }
  }
  scene.vertexCount = position.vertexCount();
  // Counter-clockwise seen from outside; the degenerate triangles at the
  // poles are left out.
  const auto vertex = [](int stack, int slice) {
    return static_cast<std::uint32_t>(stack * (kSlices + 1) + slice);
  };
  for (int stack = 0; stack < kStacks; ++stack)
    for (int slice = 0; slice < kSlices; ++slice) {
      if (stack > 0)
        scene.indices.insert(scene.indices.end(), {vertex(stack, slice), vertex(stack, slice + 1),
                                                   vertex(stack + 1, slice)});
      if (stack + 1 < kStacks)
        scene.indices.insert(scene.indices.end(), {vertex(stack, slice + 1),
                                                   vertex(stack + 1, slice + 1),
                                                   vertex(stack + 1, slice)});
    }
  scene.environment = std::make_shared<const CubeMap>(makeEnvironment());
  scene.attributes["position"] = std::move(position);
  scene.attributes["normal"] = std::move(normal);
  const Vec3d eye = {0.3, 0.5, 3.0};
  addCameraValues(scene, rotation({0.0, 1.0, 0.3}, 20.0 * kPi / 180), lookAt(eye, {0, 0, 0}, {0, 1, 0}),
                  eye, perspective(45.0 * kPi / 180, 1.0, 0.5, 10.0));
  return scene;
}

// Incidence-angle sweep: each vertex is placed in front of the camera and
// given a normal at a chosen angle to the view ray, with the samples dense
// at normal incidence, at grazing incidence and just past it, where methods
// fail first. Eye space equals model space, so the normal is used as given.
Scene sweep() {
  Scene scene;
  scene.name = "sweep";
  scene.description = "incidence angles 0 to 90 degrees and just past, dense at both ends";
  constexpr int kCount = 4096;
  std::mt19937_64 random(20261121);  // raw 64-bit output is the same on every platform
  auto uniform = [&] { return static_cast<double>(random() >> 11) * 0x1.0p-53; };
  AttributeStream position{"position", 4, {}}, normal{"normal", 3, {}};
  for (int k = 0; k < kCount; ++k) {
    const double t = static_cast<double>(k) / (kCount - 1);
    double angle;  // incidence angle in degrees
    if (k < kCount / 2) angle = 90.0 * (2 * t);                          // uniform 0..90
    else if (k < 3 * kCount / 4) angle = 90.0 * (1 - std::pow(10.0, -1 - 6 * (4 * t - 2)));  // to grazing
    else angle = 90.0 + 10.0 * std::pow(10.0, -5 * (4 * t - 3));          // just past grazing
    // View direction within 30 degrees of -z, at a distance of 2 to 6.
    const double polar = 30.0 * kPi / 180 * std::sqrt(uniform()), azimuth = 2 * kPi * uniform();
    const Vec3d d = {std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth),
                     -std::cos(polar)};
    const double distance = 2 + 4 * uniform();
    // The normal is -d turned by `angle` about an axis perpendicular to d.
    const Vec3d helper = std::abs(d[0]) < 0.9 ? Vec3d{1, 0, 0} : Vec3d{0, 1, 0};
    const Vec3d u = normalized(cross(d, helper)), w = cross(d, u);
    const double spin = 2 * kPi * uniform();
    const double a = angle * kPi / 180;
    Vec3d n;
    for (int c = 0; c < 3; ++c)
      n[c] = -d[c] * std::cos(a) + (u[c] * std::cos(spin) + w[c] * std::sin(spin)) * std::sin(a);
    for (int c = 0; c < 3; ++c) position.data.push_back(static_cast<float>(distance * d[c]));
    position.data.push_back(1.0f);
    for (int c = 0; c < 3; ++c) normal.data.push_back(static_cast<float>(n[c]));
  }
  scene.vertexCount = kCount;
  scene.attributes["position"] = std::move(position);
  scene.attributes["normal"] = std::move(normal);
  addCameraValues(scene, identity4(), identity4(), {0, 0, 0},
                  perspective(60.0 * kPi / 180, 1.0, 0.5, 10.0));
  return scene;
}

}  // namespace

std::vector<std::string> sceneNames() { return {"sphere", "sweep"}; }

Scene makeScene(const std::string& name) {
  if (name == "sphere") return sphere();
  if (name == "sweep") return sweep();
  throw UsageError(fmt::format("unknown scene `{}`; known scenes: {}", name,
                               fmt::join(sceneNames(), ", ")));
}

}  // namespace snell
