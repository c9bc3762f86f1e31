#include "bench/fresnel_reference_image.h"

#include <fmt/format.h>

#include <cmath>

#include "bench/sphere_view.h"
#include "core/errors.h"
#include "oracle/physics/fresnel.h"

namespace snell::bench {

ReferenceImage fresnelReferenceImage(const Scene& scene, double eta, int width, int height) {
  const SphereView view(scene);
  if (!(eta > 0.0 && eta < 1.0))
    throw UsageError(fmt::format("Eta {} is not n1/n2 from air into glass (0 < Eta < 1)", eta));
  ReferenceImage out{Image(width, height),
                     std::vector<bool>(static_cast<std::size_t>(width) * height),
                     std::vector<float>(static_cast<std::size_t>(width) * height)};
  view.forEachHit(width, height, [&](const SphereHit& hit) {
    const double r = physics::fresnelExact(hit.cosIncident, 1.0, 1.0 / eta).unpolarised;
    const Rgba reflectColor = view.environment(reflectDirection(hit.incident, hit.normal));
    const Rgba refractColor = view.environment(refractDirection(hit.incident, hit.normal, eta));
    float* pixel = out.color.at(hit.x, hit.y);
    for (int c = 0; c < 3; ++c)
      pixel[c] = static_cast<float>((1.0 - r) * refractColor[c] + r * reflectColor[c]);
    pixel[3] = 1.0f;
    out.covered[static_cast<std::size_t>(hit.y) * width + hit.x] = true;
    out.incidenceDeg[static_cast<std::size_t>(hit.y) * width + hit.x] =
        static_cast<float>(std::acos(hit.cosIncident) * 180.0 / M_PI);
  });
  return out;
}

}  // namespace snell::bench
