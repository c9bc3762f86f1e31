#pragma once
// The procedural decal every drawing scene binds to `scene.decal`: a 2D
// RGBA32F texture for listings that mix a surface colour into the
// environment (the Cg Tutorial's decalMap). Designed as the environment
// is, so that errors show: a smooth colour ramp in both directions, and dark
// grid lines every 1/8 of the texture, so a texture coordinate that is off,
// swapped or flipped moves visible lines. It is periodic in s and t, so the
// REPEAT wrap that backends and the CPU reference use has no seam, and its
// largest step between neighbouring texels (wrap included) is small and
// known, which is what the image tolerances are derived from.
//
// Texel (i, j) is image.at(i, j) and covers s in [i/width, (i+1)/width], t
// in [j/height, (j+1)/height]: row j of the data is row j of the texture
// (GL's "bottom" row first), uploaded without a flip on both APIs.
#include "core/image.h"

namespace snell {

Image makeDecal(int size = 128);

// The largest difference of any channel between two texels that a bilinear
// footprint with REPEAT wrapping can mix: horizontal and vertical
// neighbours, the last column with the first and the last row with the first.
double largestNeighbourStep(const Image& decal);

}  // namespace snell
