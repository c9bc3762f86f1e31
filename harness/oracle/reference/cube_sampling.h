#pragma once
// Cube map sampling as the specs define it, evaluated in double: face
// selection and (s, t) from OpenGL 4.6 section 8.13 (table 8.19) and the
// Vulkan "Cube Map Face Selection and Transformations" table, which agree;
// texel selection and filtering from OpenGL 4.6 section 8.14 and the Vulkan
// "Texel Coordinate Systems" and "Cube Map Edge Handling" sections. Base
// level only: scenes use no mipmaps.
#include <array>

#include "core/cube_map.h"

namespace snell {

using Direction = std::array<double, 3>;
using Rgba = std::array<double, 4>;

// Face indices in CubeMap::faces order.
inline constexpr int kPositiveX = 0;
inline constexpr int kNegativeX = 1;
inline constexpr int kPositiveY = 2;
inline constexpr int kNegativeY = 3;
inline constexpr int kPositiveZ = 4;
inline constexpr int kNegativeZ = 5;

struct FaceCoordinates {
  int face = kPositiveX;
  double s = 0.5;  // [0, 1] across the face
  double t = 0.5;
};

// The major axis face and (s, t) of a nonzero direction. Ties in magnitude
// are broken as the Vulkan spec recommends: z wins over y and x, then y over
// x (both specs only require a deterministic rule of the direction alone).
FaceCoordinates selectCubeFace(const Direction& direction);

// The filtered value at a nonzero direction: NEAREST or LINEAR within the
// selected face; LINEAR footprints that cross a face edge take texels from
// the adjacent face when map.seamless, and clamp to the face's edge texels
// (CLAMP_TO_EDGE) otherwise.
Rgba sampleCube(const CubeMap& map, const Direction& direction);

// How close, relative to |ma|, the two largest direction components may be
// before the face a GPU selects is no longer certain. The direction a
// fragment looks up is an fp32 varying: its components carry the rounding
// of the vertex stage's last transform (a 4-term dot product: up to about 8
// ULPs of the largest component) and of perspective-correct interpolation
// (about 8 more). The test compares two such components, so their errors
// add: 2 * 16 = 32 ULPs of |ma|, i.e. 32 * 2^-24 = 2^-19.
inline constexpr double kFaceEdgeRelativeEpsilon = 0x1p-19;

// Whether |ma| minus the second-largest magnitude is within
// kFaceEdgeRelativeEpsilon * |ma|: a direction on (or at the corner of) a
// face edge. False for the zero direction, whose lookup is undefined anyway.
bool nearCubeFaceEdge(const Direction& direction);

}  // namespace snell
