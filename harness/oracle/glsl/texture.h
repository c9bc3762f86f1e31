#pragma once
// GLSL's samplerCube, sampler2D and texture() for the fragment parts of listings,
// in double only: the reference image is gated per pixel with explicit
// thresholds, not intervals. A lookup also notes what the image gate must
// leave out: a direction the spec leaves undefined, and one so close to a
// face edge that a GPU's fp32 direction may select the other face.
#include "core/cube_map.h"
#include "core/image.h"
#include "oracle/glsl/vector.h"

namespace snell::glsl {

struct samplerCube {
  const CubeMap* map = nullptr;
  // What this fragment's lookups ran into.
  bool undefinedLookup = false;  // a zero (refract's total internal reflection) or NaN direction
  bool faceEdgeLookup = false;   // a direction within kFaceEdgeRelativeEpsilon of a face edge,
                                 // where the filter makes the edge a discontinuity
};

// The filtered texel value. A zero or NaN direction selects no face: the
// result is 0 and the lookup is marked undefined.
vec4<double> texture(samplerCube& sampler, const vec3<double>& P);

// A 2D texture as RenderJob::textures2D binds it: LINEAR, REPEAT, base level.
struct sampler2D {
  const Image* image = nullptr;
  bool undefinedLookup = false;  // a NaN or infinite coordinate, which wraps to no texel
};

// The filtered texel value (oracle/reference/texture_2d_sampling.h). A
// coordinate that is not finite gives 0 and marks the lookup undefined.
vec4<double> texture(sampler2D& sampler, const vec2<double>& P);

}  // namespace snell::glsl
