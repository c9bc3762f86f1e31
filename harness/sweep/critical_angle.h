#pragma once
// Where refract() switches to the zero vector (total internal reflection) on
// each backend, against the closed form asin(n2 / n1).
#include <string>
#include <vector>

#include "sweep/sweep_observation.h"
#include "sweep/sweep_points.h"

namespace snell::sweep {

struct CriticalAngle {
  std::string backend;
  double eta = 0;                   // n1 / n2 > 1
  double closedFormDegrees = 0;     // asin(n2 / n1), the physics reference
  double lastRefractedDegrees = 0;  // largest angle with a non-zero result below the switch
  double firstZeroDegrees = 0;      // smallest angle with the zero vector
  double foundDegrees = 0;          // midpoint of the two
  double resolutionDegrees = 0;     // their distance
  // Half-width of the band around the closed form where the spec allows
  // either way (k's interval straddles 0): a backend may switch anywhere in it.
  double specBandDegrees = 0;
  // How far rounding eta and I to fp32 can move the switch: with N = (0, 1, 0),
  // k = 1 - eta^2 (1 - I.y^2); a relative error a in eta moves the critical
  // angle by a tan(theta_c), one b in I.y = -cos(theta) by b / tan(theta_c);
  // |a|, |b| <= 2^-24. Points closer than this to the closed form may fall
  // either way.
  double inputRoundingDegrees = 0;
  int wrongSide =
      0;  // points on the wrong side of the closed form where the spec allows only one way
  // One clean step, no point on the wrong side, and the switch within half
  // the resolution (plus the spec's band and the input rounding) of the
  // closed form.
  bool agrees = false;
};

// Whether the spec allows refract() both ways here (k's interval straddles
// 0): the hull of the allowed x components reaches both 0 and the refracted
// ray's x (eta sin(theta), near 1 at the critical angle).
bool bothWaysAllowed(const Observation& oracle);

// One entry per eta > 1 of the grid. `oracle` says where the spec allows
// either way; `sweep` is the backend judged.
std::vector<CriticalAngle> criticalAngles(const std::vector<SweepPoint>& points,
                                          const BackendSweep& oracle, const BackendSweep& sweep);

}  // namespace snell::sweep
