#pragma once
// The physics reference for the refraction method ladder, and the
// geometric steps of the ablation table: per pixel, the eye ray traced
// through the analytic unit sphere (oracle/physics/analytic_sphere.h):
// reflected at entry, refracted in, and at each hit from inside split into
// the transmitted part, which looks the environment up, and the reflected
// part, which goes on (exact Fresnel, total internal reflection); the
// energy still inside after the last hit followed is dropped.
#include "bench/fresnel_reference_image.h"
#include "core/scene.h"

namespace snell::bench {

// Hits from inside the reference follows: the ablation table shows the
// next one changes nothing the metrics see (`snell bench`, ablation.json).
inline constexpr int kReferenceInternalHits = 8;

inline constexpr const char* kSphereTraceReferenceModel =
    "the analytic unit sphere traced through both interfaces and its internal reflections "
    "(exact unpolarised Fresnel at each hit, total internal reflection), each ray that leaves "
    "weighted by the energy it carries, the energy still inside after the last hit dropped; "
    "environment looked up through the scene's texture matrix with bilinear base-level cube "
    "sampling";

// index: the sphere's (air outside); internalHits: surface hits from inside
// followed (1 is the second interface).
ReferenceImage sphereTraceImage(const Scene& scene, double index, int internalHits, int size);

}  // namespace snell::bench
