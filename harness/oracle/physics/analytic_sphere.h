#pragma once
// A ray from an environment at infinity through a homogeneous sphere: it is
// reflected at entry or refracted in, then each time it meets the surface
// from inside it splits into a transmitted ray (which leaves for the
// environment) and a reflected one (which stays inside), with the exact
// Fresnel reflectance and total internal reflection. The rays that leave,
// each with the fraction of the incoming energy it carries, are what a
// renderer looks up in the environment. Nothing is absorbed, so the
// weights and the energy still inside when the trace stops sum to 1.
#include <vector>

#include "oracle/physics/vector3.h"

namespace snell::physics {

struct Sphere {
  Vec3 centre;
  double radius = 1.0;
  double index = 1.5;         // inside
  double outsideIndex = 1.0;  // the medium the environment is seen through
};

enum class ExitKind {
  Missed,            // the ray passes the sphere by
  ReflectedAtEntry,  // reflected off the outside
  Refracted,         // entered, left after internalReflections reflections inside
};

struct SphereExit {
  ExitKind kind = ExitKind::Missed;
  int internalReflections = 0;
  Vec3 origin;     // where it leaves the surface (the ray's origin when missed)
  Vec3 direction;  // unit, towards the environment
  double weight = 0.0;
};

struct SphereTrace {
  std::vector<SphereExit> exits;
  double remaining = 0.0;  // energy still inside when the trace stopped
  int internalHits = 0;    // surface hits from inside that were followed
};

struct SphereTraceLimits {
  int maxInternalHits = 8;       // surface hits from inside to follow
  double stopBelowEnergy = 0.0;  // stop early once the energy inside is below this
};

// `direction` need not be unit length. Bad input (a zero direction, a
// radius or index that is not a finite positive number) throws UsageError.
SphereTrace traceSphere(const Sphere& sphere, Vec3 origin, Vec3 direction,
                        const SphereTraceLimits& limits = {});

}  // namespace snell::physics
