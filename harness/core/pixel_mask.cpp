#include "core/pixel_mask.h"

namespace snell {

const char* pixelMaskName(PixelMask mask) {
  switch (mask) {
    case PixelMask::None:
      return "none";
    case PixelMask::Silhouette:
      return "silhouette";
    case PixelMask::FaceEdge:
      return "face-edge";
    case PixelMask::Undefined:
      return "undefined";
  }
  return "?";
}

}  // namespace snell
