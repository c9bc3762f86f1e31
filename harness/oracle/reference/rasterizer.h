#pragma once
// Which triangle each pixel shows and where on it: the fixed-function part
// of drawing an indexed triangle list as OpenGL does, evaluated in double.
// Clip space to window coordinates with the viewport covering the image and
// the depth range [0, 1] (y up, then flipped so that row 0 is the top);
// back-face culling of counter-clockwise front faces; pixel centres at
// (x + 0.5, y + 0.5); a top-left fill rule; depth test LESS against a depth
// buffer cleared to 1; perspective-correct vertex weights.
#include <array>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

namespace snell {

struct ClipPosition {
  double x = 0, y = 0, z = 0, w = 1;
};

struct RasterSettings {
  int width = 0;
  int height = 0;
  bool cullBackFaces = true;
};

// Per pixel, row 0 at the top.
struct Visibility {
  static constexpr std::uint32_t kNoTriangle = std::numeric_limits<std::uint32_t>::max();

  int width = 0;
  int height = 0;
  // The visible triangle (its position in the triangle list), or kNoTriangle.
  std::vector<std::uint32_t> triangle;
  // The perspective-correct weights of that triangle's three vertices, in
  // index order: a vertex output interpolates to sum(weights[k] * value[k]).
  std::vector<std::array<double, 3>> weights;

  bool covered(int x, int y) const {
    return triangle[static_cast<std::size_t>(y) * width + x] != kNoTriangle;
  }
};

// Throws UsageError when the indices are not a triangle list over
// `positions`, a position is not finite, or a triangle crosses the plane
// w = 0 (scenes keep their geometry in front of the camera; a triangle wholly
// outside one clip plane is dropped, as clipping would drop it).
Visibility rasterize(std::span<const ClipPosition> positions,
                     std::span<const std::uint32_t> indices, const RasterSettings& settings);

}  // namespace snell
