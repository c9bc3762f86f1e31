#pragma once
// Where a listing breaks in the sweep, per backend, and whose fault it is.
// Spec checks (the oracle's interval for the listing as written): NaN and
// infinity, results outside the interval, backends that disagree, jumps
// between neighbouring angles. Sanity checks (the listing's outputs held
// against the geometry they stand for): a Fresnel weight outside [0, 1]
// (above 1 the reflection carries more light than arrives: energy grows), a
// weight that falls toward grazing incidence, a refracted direction on the
// wrong side of the surface, a weight far from exact Fresnel, and per-vertex
// weights interpolated across a silhouette triangle, a refracted or
// reflected direction off Snell's law or the mirror law by more than
// kDirectionBoundDegrees. A sanity break is the
// method's when the listing evaluated in double does it too. No graphics
// API here.
#include <map>
#include <string>
#include <vector>

#include "core/expected_values.h"
#include "core/values.h"
#include "sweep/listing_geometry.h"
#include "sweep/sweep_classify.h"

namespace snell::sweep {

// What a captured output stands for, from its name: a refracted direction
// (Refract*, T), a reflected one (Reflect*), a Fresnel weight (any other
// float: Ratio), or nothing the sanity checks know (colours, positions).
// Largest angle between a listing's refracted or reflected direction and
// the physical one before the sweep calls it a method break: one texel of
// the scenes' environment (a 128-texel cube face spans 90 degrees, so
// 90 / 128 = 0.70 degrees), the smallest turn a cube-map lookup can show.
constexpr double kDirectionBoundDegrees = 90.0 / 128.0;

enum class OutputRole { Refracted, Reflected, Weight, Other };
OutputRole outputRole(const std::string& name, int components);

struct ListingBreak {
  std::string listing;
  std::string output;
  std::string backend;  // "gl", "vk", "gl|vk" for a disagreement
  std::string frame;    // "unit" or "stretched"
  std::string input;    // "grid", "back-face", a bad input, or "draw" (the whole draw)
  double eta = 0;       // the listing's main eta in this draw (0: it has none)
  double angleDegrees = 0;
  std::string kind;
  BreakClass cls = BreakClass::Implementation;
  std::string detail;
  std::vector<double> value;
};

// One draw of one listing as the classifier sees it.
struct ListingDrawView {
  std::string listing, frame;
  double eta = 0;
  const std::vector<ListingPoint>* points = nullptr;
  // The eta a refracted output is computed with, where it is not the main
  // one (RefractR with EtaR): its critical angle is asin(1 / that).
  std::map<std::string, double> outputEta;
  // False where a literal matrix in the manifest turns the listing's
  // directions (the blog's texture unit 1): the direction checks are skipped.
  bool directionsInEyeSpace = true;
  double etaOf(const std::string& output) const {
    const auto it = outputEta.find(output);
    return it == outputEta.end() ? eta : it->second;
  }
};

// One backend's answer to the draw, with the oracle's for that backend's rules.
struct ListingBackendView {
  std::string backend;
  bool answered = true;
  std::string problem;  // when not answered, or the draw could not be set up
  bool compiled = true;
  std::string log;  // the compiler's, when it did not compile
  const std::vector<OracleVarying>* expected = nullptr;
  const std::vector<CapturedVarying>* observed = nullptr;
  bool timedOut = false;  // not answered within --timeout: kind timeout, not crash
};

// Every break of one draw on one backend.
std::vector<ListingBreak> classifyListingDraw(const ListingDrawView& draw,
                                              const ListingBackendView& backend);

// Points where two backends differ by more than either interval is wide.
std::vector<ListingBreak> listingDisagreements(const ListingDrawView& draw,
                                               const ListingBackendView& a,
                                               const ListingBackendView& b);

// Where a refracted output switches to the zero vector along the front-facing
// angles of a draw (eta > 1): the listing's own total internal reflection
// boundary, against asin(1 / eta).
struct ListingCriticalAngle {
  std::string listing, output, backend, frame;
  double eta = 0;
  double closedFormDegrees = 0;
  double lastRefractedDegrees = 0, firstZeroDegrees = 0;
  double foundDegrees = 0;  // their midpoint
  bool found = false;       // a zero vector appeared after a refracted one
};
std::vector<ListingCriticalAngle> listingCriticalAngles(const ListingDrawView& draw,
                                                        const ListingBackendView& backend);

}  // namespace snell::sweep
