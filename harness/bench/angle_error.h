#pragma once
// A method's error against the physics reference by angle of incidence:
// where on the sphere (normal incidence at its centre, grazing at its rim)
// a method departs from physics.
#include <vector>

#include "bench/fresnel_reference_image.h"
#include "bench/image_error.h"

namespace snell::bench {

struct AngleBin {
  double fromDeg = 0;
  double toDeg = 0;
  ImageError error;  // over the pixels both cover whose incidence is in [from, to)
};

// Bins of `binDeg` degrees from 0 to 90; empty when the reference gives no
// incidence angles.
std::vector<AngleBin> errorByAngle(const Image& rendered, const ReferenceImage& reference,
                                   double binDeg = 10.0);

}  // namespace snell::bench
