#pragma once
// The coverage-based part of a reference image's mask.
#include <cstdint>
#include <vector>

#include "oracle/reference/rasterizer.h"

namespace snell {

// 1 for each pixel whose 3x3 neighbourhood (cut at the image border) holds
// both covered and uncovered pixels: where the fill rule and sub-pixel
// precision of an implementation may cover a pixel that the reference does
// not, or the other way round.
std::vector<std::uint8_t> silhouettePixels(const Visibility& visibility);

}  // namespace snell
