#include "bench/sphere_view.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/errors.h"

namespace snell::bench {
namespace {

using physics::Vec3;

const Scene& sphereScene(const Scene& scene) {
  requireSphereScene(scene.name);
  if (!scene.environment)
    throw UsageError(
        fmt::format("scene {} has no environment; the physics reference needs the "
                    "sphere scene's",
                    scene.name));
  return scene;
}

const std::vector<float>& matrix(const Scene& scene, const char* name) {
  const auto found = scene.values.find(name);
  if (found == scene.values.end() || found->second.data.size() != 16)
    throw UsageError(
        fmt::format("scene {} has no {} matrix; the physics reference needs the "
                    "sphere scene",
                    scene.name, name));
  return found->second.data;
}

}  // namespace

void requireSphereScene(const std::string& sceneName) {
  if (sceneName != "sphere")
    throw UsageError(
        fmt::format("the physics reference models the analytic sphere only; "
                    "bench the `sphere` scene, not `{}`",
                    sceneName));
}

Vec3 reflectDirection(Vec3 d, Vec3 n) { return d - (2.0 * physics::dot(n, d)) * n; }

Vec3 refractDirection(Vec3 d, Vec3 n, double eta) {
  const double cosI = -physics::dot(d, n);
  const double k = 1.0 - eta * eta * (1.0 - cosI * cosI);
  if (k < 0.0) return Vec3{};
  return (eta * d) + ((eta * cosI - std::sqrt(k)) * n);
}

SphereView::SphereView(const Scene& scene)
    : scene_(sphereScene(scene)),
      projection_(matrix(scene, "projection")),
      texture_(matrix(scene, "texture_matrix")) {
  // The model matrix is a rotation: the unit sphere's centre in eye space is
  // the modelview's translation.
  const std::vector<float>& modelview = matrix(scene, "modelview");
  centre_ = Vec3{modelview[12], modelview[13], modelview[14]};
}

void SphereView::forEachHit(int width, int height,
                            const std::function<void(const SphereHit&)>& visit) const {
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const double ndcX = (x + 0.5) / width * 2.0 - 1.0;
      const double ndcY = 1.0 - (y + 0.5) / height * 2.0;  // row 0 at the top
      const Vec3 d = physics::normalize(Vec3{ndcX / projection_[0], ndcY / projection_[5], -1.0});
      const double b = physics::dot(d, centre_);
      const double disc = b * b - physics::dot(centre_, centre_) + 1.0;
      if (disc < 0.0) continue;
      const double t = b - std::sqrt(disc);
      const Vec3 point = t * d;
      const Vec3 n = point - centre_;  // unit: the hit is on the unit sphere
      visit({x, y, d, point, n, std::clamp(-physics::dot(d, n), 0.0, 1.0)});
    }
  }
}

// vec3(TextureMatrix * vec4(d, 1.0)), as the methods write it.
Rgba SphereView::environment(Vec3 d) const {
  const std::vector<float>& t = texture_;
  Direction out{};
  for (int row = 0; row < 3; ++row)
    out[row] = t[row] * d.x + t[4 + row] * d.y + t[8 + row] * d.z + t[12 + row];
  return sampleCube(*scene_.environment, out);
}

}  // namespace snell::bench
