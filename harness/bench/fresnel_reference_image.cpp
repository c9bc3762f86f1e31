#include "bench/fresnel_reference_image.h"

#include <fmt/format.h>

#include <cmath>

#include "core/errors.h"
#include "oracle/physics/fresnel.h"
#include "oracle/physics/vector3.h"
#include "oracle/reference/cube_sampling.h"

namespace snell::bench {
namespace {

using physics::Vec3;

const std::vector<float>& matrix(const Scene& scene, const char* name) {
  const auto found = scene.values.find(name);
  if (found == scene.values.end() || found->second.data.size() != 16)
    throw UsageError(
        fmt::format("scene {} has no {} matrix; the Fresnel reference needs the "
                    "sphere scene",
                    scene.name, name));
  return found->second.data;
}

// The environment direction the methods look up: vec3(TextureMatrix * vec4(d, 1.0)).
Direction lookupDirection(const std::vector<float>& t, Vec3 d) {
  Direction out{};
  for (int row = 0; row < 3; ++row)
    out[row] = t[row] * d.x + t[4 + row] * d.y + t[8 + row] * d.z + t[12 + row];
  return out;
}

}  // namespace

ReferenceImage fresnelReferenceImage(const Scene& scene, double eta, int width, int height) {
  if (scene.name != "sphere" || !scene.environment)
    throw UsageError(
        fmt::format("the Fresnel reference models the analytic sphere only; "
                    "bench the `sphere` scene, not `{}`",
                    scene.name));
  if (!(eta > 0.0 && eta < 1.0))
    throw UsageError(fmt::format("Eta {} is not n1/n2 from air into glass (0 < Eta < 1)", eta));
  const std::vector<float>& modelview = matrix(scene, "modelview");
  const std::vector<float>& projection = matrix(scene, "projection");
  const std::vector<float>& texture = matrix(scene, "texture_matrix");
  // The model matrix is a rotation: the unit sphere's centre in eye space is
  // the modelview's translation.
  const Vec3 centre{modelview[12], modelview[13], modelview[14]};

  ReferenceImage out{Image(width, height),
                     std::vector<bool>(static_cast<std::size_t>(width) * height)};
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const double ndcX = (x + 0.5) / width * 2.0 - 1.0;
      const double ndcY = 1.0 - (y + 0.5) / height * 2.0;  // row 0 at the top
      const Vec3 d = physics::normalize(Vec3{ndcX / projection[0], ndcY / projection[5], -1.0});
      const double b = physics::dot(d, centre);
      const double disc = b * b - physics::dot(centre, centre) + 1.0;
      if (disc < 0.0) continue;
      const double t = b - std::sqrt(disc);
      const Vec3 n = (t * d) - centre;  // unit: the hit is on the unit sphere
      const double cosI = std::min(1.0, std::max(0.0, -physics::dot(d, n)));
      const Vec3 reflected = d - (2.0 * physics::dot(n, d)) * n;
      const double k = 1.0 - eta * eta * (1.0 - cosI * cosI);
      const Vec3 refracted = (eta * d) + ((eta * cosI - std::sqrt(std::max(k, 0.0))) * n);
      const double r = physics::fresnelExact(cosI, 1.0, 1.0 / eta).unpolarised;
      const Rgba reflectColor = sampleCube(*scene.environment, lookupDirection(texture, reflected));
      const Rgba refractColor = sampleCube(*scene.environment, lookupDirection(texture, refracted));
      float* pixel = out.color.at(x, y);
      for (int c = 0; c < 3; ++c)
        pixel[c] = static_cast<float>((1.0 - r) * refractColor[c] + r * reflectColor[c]);
      pixel[3] = 1.0f;
      out.covered[static_cast<std::size_t>(y) * width + x] = true;
    }
  }
  return out;
}

}  // namespace snell::bench
