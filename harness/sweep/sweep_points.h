#pragma once
// The points `snell sweep` evaluates refract() and reflect() at: incidence
// angle against eta (dense near each critical angle and near grazing) and
// the inputs the listings assume away (unnormalized, back-facing, zero,
// denormal, huge, NaN, infinite). No graphics API here.
#include <string>
#include <vector>

#include "oracle/builtin_probe.h"

namespace snell::sweep {

struct SweepPoint {
  BuiltinCall call;
  std::string input = "grid";  // "grid", or which bad input this is ("nan-I", ...)
  double angleDegrees = 0;     // incidence angle the direction was built from
  double eta = 1;              // eta as asked for (refract), before rounding to fp32
};

struct SweepGrid {
  std::vector<double> etas;             // refract's eta values
  std::vector<double> angles;           // degrees, shared by every eta
  std::vector<double> criticalOffsets;  // radians either side of each critical angle
};

// The full grid: eta 0.3 to 2.5 by 0.1, exactly 1, 1.5 and 1/1.5, and every
// eta printed in the catalog's sources; angles 0 to 90 by 1 degree, 89 to 90
// by 0.05, and 1e-1 to 1e-4 degrees short of grazing; around each critical
// angle, offsets from 5e-7 to 5e-2 rad.
SweepGrid fullGrid();
// A few etas and angles, for tests: the same construction, smaller.
SweepGrid quickGrid();

// The critical angle, in radians, of refract() with this eta (eta > 1:
// light leaving the denser side): asin(1 / eta), the closed form
// asin(n2 / n1) with eta = n1 / n2.
double criticalAngleRadians(double eta);

// Every refract point (each eta at each angle and its critical offsets),
// then reflect at every angle, then the bad inputs for both functions.
std::vector<SweepPoint> sweepPoints(const SweepGrid& grid);

// The angles (degrees, sorted, unique) refract is evaluated at for `eta`.
std::vector<double> anglesFor(const SweepGrid& grid, double eta);

}  // namespace snell::sweep
