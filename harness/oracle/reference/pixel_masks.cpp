#include "oracle/reference/pixel_masks.h"

#include <algorithm>

#include "oracle/reference/reference_image.h"

namespace snell {


std::size_t ReferenceImage::count(PixelMask m) const {
  return static_cast<std::size_t>(std::count(mask.begin(), mask.end(), m));
}

std::vector<std::uint8_t> silhouettePixels(const Visibility& visibility) {
  const int width = visibility.width, height = visibility.height;
  std::vector<std::uint8_t> silhouette(static_cast<std::size_t>(width) * height, 0);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      bool anyCovered = false, anyUncovered = false;
      for (int ny = std::max(0, y - 1); ny <= std::min(height - 1, y + 1); ++ny) {
        for (int nx = std::max(0, x - 1); nx <= std::min(width - 1, x + 1); ++nx) {
          if (visibility.covered(nx, ny)) {
            anyCovered = true;
          } else {
            anyUncovered = true;
          }
        }
      }
      silhouette[static_cast<std::size_t>(y) * width + x] = anyCovered && anyUncovered;
    }
  }
  return silhouette;
}

}  // namespace snell
