#include "core/environment.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <numbers>

namespace snell {
namespace {

// The direction through the centre of texel (i, j) of face f, following the
// major-axis table of the GL/Vulkan specs (sc, tc, ma per face).
void texelDirection(int face, double s, double t, double out[3]) {
  const double sc = 2 * s - 1, tc = 2 * t - 1;
  switch (face) {
    case 0: out[0] = 1, out[1] = -tc, out[2] = -sc; break;   // +X
    case 1: out[0] = -1, out[1] = -tc, out[2] = sc; break;   // -X
    case 2: out[0] = sc, out[1] = 1, out[2] = tc; break;     // +Y
    case 3: out[0] = sc, out[1] = -1, out[2] = -tc; break;   // -Y
    case 4: out[0] = sc, out[1] = -tc, out[2] = 1; break;    // +Z
    default: out[0] = -sc, out[1] = -tc, out[2] = -1; break; // -Z
  }
  const double length = std::sqrt(out[0] * out[0] + out[1] * out[1] + out[2] * out[2]);
  for (int c = 0; c < 3; ++c) out[c] /= length;
}

// A raised-cosine line profile: 1 on a grid line, 0 beyond half a width.
double gridLine(double u) {
  constexpr double kLines = 8;          // lines per face, face edges included
  constexpr double kHalfWidth = 0.03;   // in face coordinates: 4 texels at size 128
  const double distance = std::abs(u * kLines - std::round(u * kLines)) / kLines;
  return distance >= kHalfWidth ? 0.0 : 0.5 * (1 + std::cos(std::numbers::pi * distance / kHalfWidth));
}

}  // namespace

CubeMap makeEnvironment(int size) {
  CubeMap map;
  map.size = size;
  for (int f = 0; f < 6; ++f) {
    std::vector<float>& face = map.faces[f];
    face.resize(static_cast<std::size_t>(size) * size * 4);
    for (int j = 0; j < size; ++j)
      for (int i = 0; i < size; ++i) {
        const double s = (i + 0.5) / size, t = (j + 0.5) / size;
        double d[3];
        texelDirection(f, s, t, d);
        const double line = 0.1 * std::max(gridLine(s), gridLine(t));
        float* texel = &face[(static_cast<std::size_t>(j) * size + i) * 4];
        for (int c = 0; c < 3; ++c) texel[c] = static_cast<float>(0.45 + 0.4 * d[c] + line);
        texel[3] = 1.0f;
      }
  }
  return map;
}

std::shared_ptr<const CubeMap> sharedEnvironment(int size) {
  static std::mutex mutex;
  static std::map<int, std::shared_ptr<const CubeMap>> made;
  const std::lock_guard lock(mutex);
  std::shared_ptr<const CubeMap>& map = made[size];
  if (!map) map = std::make_shared<const CubeMap>(makeEnvironment(size));
  return map;
}

double largestNeighbourStep(const CubeMap& map) {
  // Within faces directly; across edges the map is continuous by
  // construction (it is a function of direction), which the test checks by
  // comparing edge texels of adjacent faces through their directions.
  double largest = 0;
  const int n = map.size;
  for (const std::vector<float>& face : map.faces)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        for (int c = 0; c < 4; ++c) {
          const float here = face[(static_cast<std::size_t>(j) * n + i) * 4 + c];
          if (i + 1 < n)
            largest = std::max(largest, double(std::abs(face[(static_cast<std::size_t>(j) * n + i + 1) * 4 + c] - here)));
          if (j + 1 < n)
            largest = std::max(largest, double(std::abs(face[(static_cast<std::size_t>(j + 1) * n + i) * 4 + c] - here)));
        }
  return largest;
}

}  // namespace snell
