#pragma once
// A linear float RGBA image, row 0 at the top (as people and OpenImageIO
// read images). Backends flip their read-back to this convention: clip-space
// +y is up in the image on both APIs.
#include <cstddef>
#include <vector>

namespace snell {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<float> pixels;  // width * height * 4, RGBA, row-major from the top

  Image() = default;
  Image(int w, int h) : width(w), height(h), pixels(static_cast<std::size_t>(w) * h * 4, 0.0f) {}
  float* at(int x, int y) { return &pixels[(static_cast<std::size_t>(y) * width + x) * 4]; }
  const float* at(int x, int y) const { return &pixels[(static_cast<std::size_t>(y) * width + x) * 4]; }
};

}  // namespace snell
