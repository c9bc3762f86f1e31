#pragma once
// 2D texture sampling as the specs define it for what RenderJob::textures2D
// binds, evaluated in double: base level only, LINEAR filtering (OpenGL 4.6
// section 8.14.2, the Vulkan "Texel Coordinate Systems" and "Texel
// Filtering" sections, which agree) and REPEAT wrapping of the integer texel
// coordinates (OpenGL table 8.20, Vulkan "Wrapping Operation": i mod size).
// Texel (i, j) is image.at(i, j): s in [i/width, (i+1)/width], t in
// [j/height, (j+1)/height].
#include <array>

#include "core/image.h"

namespace snell {

using Rgba = std::array<double, 4>;  // the same type as cube_sampling.h names

// The filtered value at (s, t), which must be finite: u = s * width - 1/2,
// i0 = floor(u) mod width, i1 = (floor(u) + 1) mod width, alpha = frac(u),
// likewise for t; the four texels weighted as the specs write them,
// (1 - alpha)(1 - beta), alpha (1 - beta), (1 - alpha) beta, alpha beta.
Rgba sampleTexture2D(const Image& image, double s, double t);

}  // namespace snell
