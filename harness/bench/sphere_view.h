#pragma once
// What every physics reference of the bench shares: the eye rays of the
// sphere scene's pixels meeting the analytic unit sphere (not the
// tessellated mesh the methods draw), and the environment looked up as the
// methods look it up (the scene's texture matrix applied to (d, 1),
// base-level bilinear cube sampling), so a reference differs from a method
// in its optics only.
#include <functional>
#include <string>

#include "core/image.h"
#include "core/scene.h"
#include "oracle/physics/vector3.h"
#include "oracle/reference/cube_sampling.h"

namespace snell::bench {

// One pixel whose eye ray meets the sphere, in eye space.
struct SphereHit {
  int x = 0, y = 0;        // row 0 at the top
  physics::Vec3 incident;  // unit, from the eye (the origin) towards the sphere
  physics::Vec3 point;     // where it first meets the surface
  physics::Vec3 normal;    // unit, outwards
  double cosIncident = 0;  // -incident . normal, in [0, 1]
};

// GLSL's reflect(d, n) and refract(d, n, eta) for unit d and n, in double;
// refract gives (0, 0, 0) past the critical angle, as GLSL does.
physics::Vec3 reflectDirection(physics::Vec3 d, physics::Vec3 n);
physics::Vec3 refractDirection(physics::Vec3 d, physics::Vec3 n, double eta);

// Throws UsageError unless `sceneName` is the sphere scene's, the one
// scene the references model: a bench checks it before any other.
void requireSphereScene(const std::string& sceneName);

class SphereView {
 public:
  // The scene must be the sphere scene (a unit sphere at the model origin
  // under a rigid modelview); throws UsageError otherwise.
  explicit SphereView(const Scene& scene);

  // Calls `visit` for each pixel centre whose eye ray meets the sphere.
  void forEachHit(int width, int height, const std::function<void(const SphereHit&)>& visit) const;

  // The environment in eye-space direction `d`.
  Rgba environment(physics::Vec3 d) const;

  physics::Vec3 centre() const { return centre_; }

 private:
  const Scene& scene_;
  const std::vector<float>& projection_;
  const std::vector<float>& texture_;
  physics::Vec3 centre_;
};

}  // namespace snell::bench
