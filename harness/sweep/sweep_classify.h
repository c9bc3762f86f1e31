#pragma once
// Where each backend breaks in a sweep, and whose fault it is:
// - implementation: the backend left the interval the spec allows (or crashed);
// - undefined: the spec allows anything there (a NaN or infinite input, a
//   component the oracle leaves open, refract()'s zero vector under total
//   internal reflection used as a direction, two backends that differ where
//   both are within the spec);
// - method: the backends are right but the method is wrong against physics
//   (method_sweep.h).
#include <string>
#include <vector>

#include "sweep/sweep_observation.h"
#include "sweep/sweep_points.h"

namespace snell::sweep {

enum class BreakClass { Implementation, Undefined, Method };
const char* breakClassName(BreakClass c);

struct Break {
  std::string function;   // "refract", "reflect", or a Fresnel method
  std::string backend;    // "oracle", "gl", "vk", "gl|vk" for a disagreement, "physics" for methods
  std::size_t point = 0;  // index into the sweep's points (builtins)
  std::string kind;       // crash, timeout, nan_or_inf_output, outside_spec, zero_vector_direction,
                          // backend_disagreement, discontinuity, ...
  BreakClass cls = BreakClass::Implementation;
  std::string detail;
  std::vector<double> value;
};

// Whether every input number (I, N, and eta for refract) is finite.
bool inputsFinite(const SweepPoint& point);

// A point's breaks on one backend: crash, NaN/inf output, outside the spec,
// refract's zero vector.
std::vector<Break> classifyPoint(const SweepPoint& point, std::size_t index,
                                 const Observation& observation, const std::string& backend);

// Two backends whose vectors differ by more than either interval is wide, or
// one NaN where the other is not.
std::vector<Break> disagreements(const std::vector<SweepPoint>& points, const BackendSweep& a,
                                 const BackendSweep& b);

// Along each grid series (one function, one eta, by angle): a jump between
// neighbours larger than the exact function's own jump plus both intervals'
// widths, which no pair of results within the spec can make.
std::vector<Break> discontinuities(const std::vector<SweepPoint>& points,
                                   const BackendSweep& sweep);

// Everything above for every backend (and every pair of backends).
std::vector<Break> classifySweep(const std::vector<SweepPoint>& points,
                                 const std::vector<BackendSweep>& sweeps);

}  // namespace snell::sweep
