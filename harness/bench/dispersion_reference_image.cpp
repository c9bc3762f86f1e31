#include "bench/dispersion_reference_image.h"

#include <array>
#include <cmath>

#include "bench/sphere_view.h"
#include "oracle/physics/cie1931.h"
#include "oracle/physics/fresnel.h"

namespace snell::bench {

ReferenceImage dispersionReferenceImage(const Scene& scene, const physics::SellmeierGlass& glass,
                                        int wavelengths, int width, int height) {
  const SphereView view(scene);
  struct Band {
    double index = 0;
    std::array<double, 3> response{};  // linear sRGB weight, bin width included
  };
  std::vector<Band> bands;
  std::array<double, 3> total{};
  for (const physics::SpectralSample& s : physics::spectralSamples(wavelengths)) {
    const physics::LinearSrgb rgb =
        physics::xyzToLinearSrgb(physics::cie1931ColourMatching(s.lambdaNm));
    Band band{physics::refractiveIndex(glass, s.lambdaNm),
              {rgb.r * s.weightNm, rgb.g * s.weightNm, rgb.b * s.weightNm}};
    for (int c = 0; c < 3; ++c) total[c] += band.response[c];
    bands.push_back(band);
  }

  ReferenceImage out{Image(width, height),
                     std::vector<bool>(static_cast<std::size_t>(width) * height),
                     std::vector<float>(static_cast<std::size_t>(width) * height)};
  view.forEachHit(width, height, [&](const SphereHit& hit) {
    const Rgba reflectColor = view.environment(reflectDirection(hit.incident, hit.normal));
    std::array<double, 3> sum{};
    for (const Band& band : bands) {
      const double r = physics::fresnelExact(hit.cosIncident, 1.0, band.index).unpolarised;
      const Rgba refractColor =
          view.environment(refractDirection(hit.incident, hit.normal, 1.0 / band.index));
      for (int c = 0; c < 3; ++c)
        sum[c] += band.response[c] * ((1.0 - r) * refractColor[c] + r * reflectColor[c]);
    }
    float* pixel = out.color.at(hit.x, hit.y);
    for (int c = 0; c < 3; ++c) pixel[c] = static_cast<float>(sum[c] / total[c]);
    pixel[3] = 1.0f;
    out.covered[static_cast<std::size_t>(hit.y) * width + hit.x] = true;
    out.incidenceDeg[static_cast<std::size_t>(hit.y) * width + hit.x] =
        static_cast<float>(std::acos(hit.cosIncident) * 180.0 / M_PI);
  });
  return out;
}

}  // namespace snell::bench
