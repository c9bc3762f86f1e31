#pragma once
// The physics reference for the Fresnel method ladder, on the CPU in double
// with no graphics API: for each pixel centre, the eye ray meets the
// analytic unit sphere (not the tessellated mesh the methods draw); at the
// hit, the environment in the reflected direction and in the direction
// refracted into the glass (one interface, as every method on the ladder)
// are mixed by the exact unpolarised Fresnel reflectance R = (Rs + Rp) / 2
// (oracle/physics/fresnel.h). The environment is looked up as the methods
// do (the scene's texture matrix applied to (d, 1), base-level bilinear
// cube sampling), so the difference is the reflectance and the geometry
// (per-vertex versus per-pixel), not the texture path.
#include <vector>

#include "core/image.h"
#include "core/scene.h"

namespace snell::bench {

inline constexpr const char* kFresnelReferenceModel =
    "exact unpolarised Fresnel reflectance (Born & Wolf 1.5.2) per pixel on the analytic unit "
    "sphere, mixing the environment in the reflected direction and in the direction refracted "
    "at the first interface (no second interface, no internal bounces), looked up through the "
    "scene's texture matrix with bilinear base-level cube sampling";

struct ReferenceImage {
  Image color;                // linear RGB, alpha 1 where the sphere is hit
  std::vector<bool> covered;  // per pixel: the ray meets the sphere
  // Per pixel, the angle of incidence at the first interface in degrees
  // (where covered; empty when the reference does not give it).
  std::vector<float> incidenceDeg;
};

// The scene must be the sphere scene (a unit sphere at the model origin
// under a rigid modelview); throws UsageError otherwise. eta = n1 / n2,
// from air into the glass.
ReferenceImage fresnelReferenceImage(const Scene& scene, double eta, int width, int height);

}  // namespace snell::bench
