#pragma once
// The reasons a pixel is left out of an image comparison: the CPU reference
// sets them, compare/ counts them.
#include <cstdint>

namespace snell {

// Why a pixel is left out of the gate. Masked pixels are counted and
// reported, never failed.
enum class PixelMask : std::uint8_t {
  None = 0,        // compared
  Silhouette = 1,  // partial coverage: fill rules and sub-pixel precision may differ
  FaceEdge = 2,    // a lookup direction within the precision bound of a cube face edge
  Undefined = 3,   // the listing is undefined here (zero refract vector fed to a lookup, NaN)
};
const char* pixelMaskName(PixelMask mask);

}  // namespace snell
