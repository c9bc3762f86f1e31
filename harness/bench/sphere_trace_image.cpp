#include "bench/sphere_trace_image.h"

#include <cmath>

#include "bench/sphere_view.h"
#include "oracle/physics/analytic_sphere.h"

namespace snell::bench {

ReferenceImage sphereTraceImage(const Scene& scene, double index, int internalHits, int size) {
  const SphereView view(scene);
  const physics::Sphere sphere{view.centre(), 1.0, index, 1.0};
  const std::size_t pixels = static_cast<std::size_t>(size) * size;
  ReferenceImage out{Image(size, size), std::vector<bool>(pixels), std::vector<float>(pixels)};
  view.forEachHit(size, size, [&](const SphereHit& hit) {
    const physics::SphereTrace trace =
        physics::traceSphere(sphere, physics::Vec3{}, hit.incident, {internalHits, 0.0});
    double sum[3] = {0, 0, 0};
    for (const physics::SphereExit& exit : trace.exits) {
      const Rgba colour = view.environment(exit.direction);
      for (int c = 0; c < 3; ++c) sum[c] += exit.weight * colour[c];
    }
    float* pixel = out.color.at(hit.x, hit.y);
    for (int c = 0; c < 3; ++c) pixel[c] = static_cast<float>(sum[c]);
    pixel[3] = 1.0f;
    const std::size_t i = static_cast<std::size_t>(hit.y) * size + hit.x;
    out.covered[i] = true;
    out.incidenceDeg[i] = static_cast<float>(std::acos(hit.cosIncident) * 180.0 / M_PI);
  });
  return out;
}

}  // namespace snell::bench
