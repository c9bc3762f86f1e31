#pragma once
// The reference image's parts derived from a listing's own text
// (oracle/reference/reference_image.h): its vertex stage evaluated in
// double for every output it writes (gl_Position and what the fragment
// stage reads), and its fragment stage's colour, texture lookups sampled as
// the specs define (oracle/glsl/texture.h) and inverse() followed. Double
// only: the image gate has explicit thresholds, not intervals.
#include <memory>

#include "derived/lower_glsl.h"
#include "oracle/reference/fragment_oracle.h"
#include "oracle/vertex_oracle.h"

namespace snell::derived {

// Throws UsageError when a stage is outside the subset (naming the
// construct and its line).
std::unique_ptr<VertexOracle> makeDerivedDrawingVertexOracle(const ShaderSource& vertex);
std::unique_ptr<FragmentOracle> makeDerivedFragmentOracle(const ShaderSource& fragment);

}  // namespace snell::derived
