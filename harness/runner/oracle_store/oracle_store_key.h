#pragma once
// The key a stored oracle result is kept under: a digest of everything the
// result depends on. `identity` says which oracle computes it and from
// what (runner/listing_oracles.h: the build of the oracle's code, the
// listing's text for a derived oracle); the input is taken whole: the
// precision rules, every uniform, constant and per-invocation input, bit
// for bit.
#include <string_view>

#include "core/content_hash.h"
#include "oracle/reference/reference_image.h"
#include "oracle/vertex_oracle.h"

namespace snell {

Digest oracleResultKey(std::string_view identity, const OracleInput& input);

// The same for a CPU reference image: the drawing oracles' identity, and
// everything the rasterizer reads (the scene's triangles, the cube maps and
// 2D textures pixel for pixel, the size, the clear colour, the culling).
Digest referenceImageKey(std::string_view identity, const ReferenceInput& input);

}  // namespace snell
