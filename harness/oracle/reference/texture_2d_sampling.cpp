#include "oracle/reference/texture_2d_sampling.h"

#include <cmath>

namespace snell {
namespace {

// REPEAT: the integer coordinate modulo the size, never negative.
int wrap(double index, int size) {
  const double wrapped = std::fmod(index, static_cast<double>(size));
  return static_cast<int>(wrapped < 0 ? wrapped + size : wrapped);
}

}  // namespace

Rgba sampleTexture2D(const Image& image, double s, double t) {
  const double u = s * image.width - 0.5;
  const double v = t * image.height - 0.5;
  const double u0 = std::floor(u), v0 = std::floor(v);
  const double alpha = u - u0, beta = v - v0;
  const int i0 = wrap(u0, image.width), i1 = wrap(u0 + 1, image.width);
  const int j0 = wrap(v0, image.height), j1 = wrap(v0 + 1, image.height);
  const float* texels[4] = {image.at(i0, j0), image.at(i1, j0), image.at(i0, j1), image.at(i1, j1)};
  const double weights[4] = {(1 - alpha) * (1 - beta), alpha * (1 - beta), (1 - alpha) * beta,
                             alpha * beta};
  Rgba result{};
  for (int c = 0; c < 4; ++c)
    for (int k = 0; k < 4; ++k) result[c] += weights[k] * texels[k][c];
  return result;
}

}  // namespace snell
