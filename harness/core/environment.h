#pragma once
// The procedural environment every drawing scene reflects and refracts.
// Designed so that errors show: each face has its own colour (R, G, B
// follow the direction's x, y, z), a grid of lines every 1/8 of a face
// moves visibly when a direction or a face is wrong, and smooth gradients
// show filtering. It is continuous across face edges, so seamless filtering
// has nothing to hide, and its largest step between neighbouring texels is
// small and known, which is what the image tolerances are derived from.
#include <memory>

#include "core/cube_map.h"

namespace snell {

CubeMap makeEnvironment(int size = 128);
// The same map, made once per size in a process and shared: every scene of
// a run draws it, and making it (a few trigonometric calls per texel) was
// a visible part of a case's fixed cost.
std::shared_ptr<const CubeMap> sharedEnvironment(int size);

// The largest difference of any channel between two texels that a bilinear
// footprint can mix (neighbours in a face and across a face edge).
double largestNeighbourStep(const CubeMap& map);

}  // namespace snell
