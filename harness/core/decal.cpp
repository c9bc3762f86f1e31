#include "core/decal.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace snell {
namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

// A raised-cosine line profile: 1 on a grid line, 0 beyond half a width.
// Lines every 1/8, the texture's edges included, so the profile is periodic.
double gridLine(double u) {
  constexpr double kLines = 8;
  constexpr double kHalfWidth = 0.04;  // in texture coordinates: 5 texels at size 128
  const double distance = std::abs(u * kLines - std::round(u * kLines)) / kLines;
  return distance >= kHalfWidth ? 0.0
                                : 0.5 * (1 + std::cos(std::numbers::pi * distance / kHalfWidth));
}

}  // namespace

Image makeDecal(int size) {
  Image decal(size, size);
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i) {
      const double s = (i + 0.5) / size, t = (j + 0.5) / size;
      // One period in each direction, in different channels, so that s and
      // t swapped or flipped change the colour: warm and bright, far from
      // the environment's colours, so that the mix's weights show.
      const double line = 0.12 * std::max(gridLine(s), gridLine(t));
      float* texel = decal.at(i, j);
      texel[0] = static_cast<float>(0.75 + 0.15 * std::cos(kTwoPi * s) - line);
      texel[1] = static_cast<float>(0.45 + 0.15 * std::sin(kTwoPi * t) - line);
      texel[2] = static_cast<float>(0.25 + 0.10 * std::cos(kTwoPi * (s + t)) - line);
      texel[3] = 1.0f;
    }
  return decal;
}

double largestNeighbourStep(const Image& decal) {
  double largest = 0;
  const int w = decal.width, h = decal.height;
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      const float* here = decal.at(i, j);
      const float* right = decal.at((i + 1) % w, j);
      const float* up = decal.at(i, (j + 1) % h);
      for (int c = 0; c < 4; ++c)
        largest = std::max(
            {largest, double(std::abs(right[c] - here[c])), double(std::abs(up[c] - here[c]))});
    }
  return largest;
}

}  // namespace snell
