#pragma once
// The vertices a listing is drawn with in `snell sweep`: each vertex is a
// sweep point, seen from the eye at the origin (eye space equals world
// space), with its normal at the point's incidence angle to the view ray.
// Two frames: "unit" (model = eye space, so the listing's inputs are the
// point's own vectors, bad ones included) and "stretched" (a non-uniformly
// scaled model: unit model-space normals that NormalMatrix turns into
// non-unit eye-space ones, so every normalize() in a listing matters). No
// graphics API here.
#include <array>
#include <string>
#include <vector>

#include "core/scene.h"
#include "sweep/sweep_points.h"

namespace snell::sweep {

// The stretched model's scale along x, y, z: unequal, and far enough from 1
// that a missing normalize() or a normal turned by the model matrix in
// place of its inverse transpose moves a direction by degrees.
constexpr std::array<double, 3> kStretch = {1.0, 2.5, 0.4};

// The spacing of the sphere scene's vertices along a great circle (96
// slices): a triangle at the silhouette shades its middle with the mean of
// vertex weights this far apart.
constexpr double kSilhouetteSpacingDegrees = 360.0 / 96.0;

struct ListingPoint {
  std::string input = "grid";  // "grid", "back-face", or the bad input ("zero-N", ...)
  double angleDegrees = 0;     // incidence angle (over 90: the normal faces away)
  // Eye-space position and normal as the vertex should have them; for a bad
  // input, exactly what the listing is given (unit frame only).
  std::array<float, 3> position{0, 0, -1};
  std::array<float, 3> normal{0, 0, 1};
  // The geometry the point stands for (unit, finite), for the sanity checks:
  // the true eye-space normal and view direction.
  std::array<double, 3> trueNormal{0, 0, 1};
  double dotNH = 0;  // diffraction listings' dot(N, H) with the true normal (points near its zero)
};

// Where a diffraction listing's dot(N, H) goes to 0: the half vector H
// between the view and the light at the vertex, for the points turned
// away from it (listingPoints adds them, labelled "dot(N,H)->0").
struct HalfVector {
  std::array<double, 3> h{0, 0, 1};
};

// The grid's angles for every eta in `etas` (dense near each critical angle
// and near grazing), the silhouette pair (90 - kSilhouetteSpacingDegrees,
// and the midpoint), back faces from 90 to 180 degrees (a back face, or the
// view from inside the object), then, when `badInputs`, the inputs the
// listings assume away.
// With `half`, also the normals turned from the view ray away from H, at
// the angle where dot(N, H) = 0 and 1e-6 to 10 degrees either side.
std::vector<ListingPoint> listingPoints(const SweepGrid& grid, const std::vector<double>& etas,
                                        bool badInputs, const HalfVector* half = nullptr);

// The half vector at the sweep's vertex (0, 0, -1) for an eye and a light
// in eye space.
HalfVector halfVectorAt(const std::array<double, 3>& eye, const std::array<double, 3>& light);

// `base` (a vectors-only scene, for its projection and samplers) with the
// points as its vertices, model = stretched ? diag(kStretch) : identity,
// the view and the texture matrix the identity (so captured directions are
// in eye space) and the eye at the origin.
Scene listingScene(const Scene& base, const std::vector<ListingPoint>& points, bool stretched);

}  // namespace snell::sweep
