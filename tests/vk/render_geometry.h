#pragma once
// Geometry for the render tests: rectangles and a closed sphere, as
// position streams (vec4) and triangle-list indices, counter-clockwise as
// OpenGL sees the front.
#include <cstdint>
#include <vector>

#include "core/values.h"

namespace snell::vktest {

struct Mesh {
  AttributeStream positions{"Position", 4, {}};
  AttributeStream normals{"Normal", 3, {}};  // filled by sphere() only
  std::vector<std::uint32_t> indices;
};

// Appends the rectangle [x0, x1] x [y0, y1] at clip-space depth z, w = 1,
// as two counter-clockwise triangles.
void addRectangle(Mesh& mesh, float x0, float y0, float x1, float y1, float z);

// Appends one triangle, in the vertex order given.
void addTriangle(Mesh& mesh, const float (&corners)[3][2], float z);

// A latitude/longitude sphere of `radius` around the origin, every
// triangle counter-clockwise seen from outside, with unit normals.
Mesh sphere(float radius, int rings, int segments);

}  // namespace snell::vktest
