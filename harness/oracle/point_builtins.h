#pragma once
// reflect(I, N) and refract(I, N, eta) on exact fp32 inputs, as `snell
// eval` gets them: the general Interval road's bounds, bit for bit, by a
// shorter road.
//
// The general road (glsl/geometric.h over Interval) dispatches every + and
// * on what its operands are and fills every field of every result. For
// inputs that are exact floats, what each intermediate value of a call is
// (an open product, a closed sum, a leaf) is known in advance, and most
// intermediate results feed their consumer only their ideal range and
// region: this road computes just those, with the same primitives
// (interval_region_bounds.h, interval_float_sets.h) in the same order, so
// the bounds are the same bits. (sqrt's formula is its float set alone:
// point_builtins.cpp says why its other steps cannot change it.) Where an
// input is outside what it mirrors
// (NaN, an infinity, a denormal, a magnitude past 2^16, one component, a
// branch the intervals cannot decide, or one they decide against the exact
// value's) it declines and the caller takes the general road.
//
// Checked against the general road on random and edge inputs under both
// rules (tests/oracle/point_builtins_test.cpp), and against the adversarial
// machine (tests/oracle/adversary). A change to the general road's bounds
// must be made here too, or those tests fail.
#include <array>
#include <span>

#include "oracle/fma_build.h"
#include "oracle/precision_rules.h"

namespace snell {

// The allowed floats of each component.
struct PointBounds {
  std::array<double, 4> lo{};
  std::array<double, 4> hi{};
};

// False where the general road must answer. I and N have the same 1 to 4
// components. `build`: which compiled build of this road runs
// (oracle/fma_build.h); the same bits either way.
bool reflectOnPoints(std::span<const float> I, std::span<const float> N, PrecisionRules rules,
                     PointBounds& out, OracleBuild build = fastestOracleBuild());

struct PointRefract : PointBounds {
  // k < 0 for every allowed value: the zero vector.
  bool totalInternalReflection = false;
};

// As reflectOnPoints. `exactTotalInternalReflection`: whether the exact evaluation
// (double, on the same inputs) took the zero-vector branch; the intervals
// must agree with it for this road to answer.
bool refractOnPoints(std::span<const float> I, std::span<const float> N, float eta,
                     bool exactTotalInternalReflection, PrecisionRules rules, PointRefract& out,
                     OracleBuild build = fastestOracleBuild());

}  // namespace snell
