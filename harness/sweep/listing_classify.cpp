#include "sweep/listing_classify.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <numbers>

#include "sweep/method_sweep.h"

namespace snell::sweep {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

// A tenth of an output's [0, 1] colour range: an interval wider than this
// no longer says what colour the listing gives.
constexpr double kIllConditionedWidth = 0.1;

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// One output at one vertex, on one backend.
struct Sample {
  std::vector<double> value, reference, lo, hi;
  bool undefined = false;
  bool finite() const {
    return std::all_of(value.begin(), value.end(), [](double x) { return std::isfinite(x); });
  }
  bool withinSpec() const {
    for (std::size_t c = 0; c < value.size(); ++c)
      if (!(value[c] >= lo[c] && value[c] <= hi[c])) return false;
    return true;
  }
  double width(std::size_t c) const {
    const double w = hi[c] - lo[c];
    return std::isfinite(w) ? w : 0.0;
  }
};

Sample sampleAt(const OracleVarying& expected, const CapturedVarying& observed, std::size_t k) {
  Sample s;
  const std::size_t n = static_cast<std::size_t>(expected.components);
  for (std::size_t c = 0; c < n; ++c) {
    const std::size_t i = k * n + c;
    s.value.push_back(observed.data.at(i));
    s.reference.push_back(expected.reference.at(i));
    s.lo.push_back(expected.lo.at(i));
    s.hi.push_back(expected.hi.at(i));
    s.undefined = s.undefined || expected.undefined.at(i) != 0;
  }
  return s;
}

bool inputFinite(const ListingPoint& p) {
  for (int c = 0; c < 3; ++c)
    if (!std::isfinite(p.position[c]) || !std::isfinite(p.normal[c])) return false;
  return true;
}

double dot3(const std::vector<double>& v, const std::array<double, 3>& n) {
  return v[0] * n[0] + v[1] * n[1] + v[2] * n[2];
}

double length3(const std::vector<double>& v) {
  return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

bool allZero(const std::vector<double>& v) {
  return std::all_of(v.begin(), v.end(), [](double x) { return x == 0.0; });
}

// A sanity break's class: the method's when the listing in double does it
// too; otherwise the backend's when it left the spec, and the spec's (it
// allows the rounding that takes the value over) when not.
BreakClass sanityClass(bool referenceBreaks, const Sample& s) {
  if (referenceBreaks) return BreakClass::Method;
  return s.withinSpec() ? BreakClass::Undefined : BreakClass::Implementation;
}

struct DrawClassifier {
  const ListingDrawView& draw;
  const ListingBackendView& backend;
  std::vector<ListingBreak> breaks;

  void add(std::size_t point, const std::string& output, std::string kind, BreakClass cls,
           std::string detail, std::vector<double> value) {
    const ListingPoint& p = (*draw.points)[point];
    breaks.push_back({draw.listing, output, backend.backend, draw.frame, p.input, draw.eta,
                      p.angleDegrees, std::move(kind), cls, std::move(detail), std::move(value)});
  }

  // NaN or infinity, and results outside the interval.
  void specChecks(std::size_t k, const std::string& name, const Sample& s) {
    const ListingPoint& p = (*draw.points)[k];
    const bool open = !inputFinite(p) || s.undefined;
    if (!s.finite()) {
      const bool allowed = open || s.withinSpec();
      add(k, name, "nan_or_inf_output",
          allowed ? BreakClass::Undefined : BreakClass::Implementation,
          !inputFinite(p) ? "a NaN or infinite input"
          : s.undefined   ? "the spec leaves a component open here (normalize of zero, ...)"
          : allowed       ? "within the interval: an overflow the spec allows"
                          : "finite inputs, outside the spec",
          s.value);
    } else if (!s.withinSpec()) {
      double worst = 0;
      for (std::size_t c = 0; c < s.value.size(); ++c)
        worst = std::max(worst, std::max(s.lo[c] - s.value[c], s.value[c] - s.hi[c]));
      add(k, name, "outside_spec", open ? BreakClass::Undefined : BreakClass::Implementation,
          fmt::format("{:.3g} outside the interval", worst), s.value);
    }
  }

  void weightChecks(std::size_t k, const std::string& name, const Sample& s) {
    const double w = s.value[0], r = s.reference[0];
    if (w > 1)
      add(k, name, "weight_above_one_energy_grows", sanityClass(r > 1, s),
          fmt::format("weight {:.7g} (listing in double {:.7g}): the reflection gets more light "
                      "than arrives and the refraction a negative share",
                      w, r),
          s.value);
    if (w < 0)
      add(k, name, "weight_below_zero", sanityClass(r < 0, s),
          fmt::format("weight {:.7g} (listing in double {:.7g})", w, r), s.value);
    const ListingPoint& p = (*draw.points)[k];
    if (draw.eta > 0 && p.input == "grid" && p.angleDegrees < 90) {
      const double exact = methodSample("exact", draw.eta, p.angleDegrees).exact;
      if (std::abs(w - exact) > kMethodErrorBound)
        add(k, name, "method_error", sanityClass(std::abs(r - exact) > kMethodErrorBound, s),
            fmt::format("weight {:.4f} against exact Fresnel {:.4f} (bound {})", w, exact,
                        kMethodErrorBound),
            s.value);
    }
  }

  void directionChecks(std::size_t k, const std::string& name, OutputRole role, const Sample& s) {
    const ListingPoint& p = (*draw.points)[k];
    if (!draw.directionsInEyeSpace) return;
    if (p.input != "grid" || s.value.size() < 3) return;
    if (role == OutputRole::Refracted) totalInternalReflection(k, name, s);
    if (allZero(s.value)) return;
    physicsDirection(k, name, role, s);
    const double length = length3(s.value);
    const double side = dot3(s.value, p.trueNormal) / length;
    const double referenceSide =
        allZero(s.reference) ? 0 : dot3(s.reference, p.trueNormal) / length3(s.reference);
    // 1e-6: far above fp32 rounding of a unit vector's components, far
    // below any real turn across the surface.
    if (role == OutputRole::Refracted && side > 1e-6)
      add(k, name, "refracted_wrong_side", sanityClass(referenceSide > 1e-6, s),
          fmt::format("cos to the true normal {:+.3g}: the ray leaves on the incident side", side),
          s.value);
    if (role == OutputRole::Reflected && side < -1e-6)
      add(k, name, "reflected_wrong_side", sanityClass(referenceSide < -1e-6, s),
          fmt::format("cos to the true normal {:+.3g}: the ray goes into the surface", side),
          s.value);
  }

  // Whether the listing's refracted ray is the zero vector exactly where
  // Snell's law has total internal reflection: 1e-6 of margin on
  // k = 1 - eta^2 sin^2 keeps fp32 rounding of the inputs out of it.
  void totalInternalReflection(std::size_t k, const std::string& name, const Sample& s) {
    const ListingPoint& p = (*draw.points)[k];
    const double eta = draw.etaOf(name);
    if (!(eta > 0)) return;
    const double cosine = p.trueNormal[2];
    const double k2 = 1 - eta * eta * (1 - cosine * cosine);
    const bool zero = allZero(s.value), referenceZero = allZero(s.reference);
    if (zero && k2 > 1e-6)
      add(k, name, "zero_where_physics_refracts", sanityClass(referenceZero, s),
          fmt::format("the zero vector (total internal reflection) where Snell's law refracts "
                      "(1 - eta^2 sin^2 = {:.3g})",
                      k2),
          s.value);
    if (!zero && k2 < -1e-6)
      add(k, name, "refracts_where_physics_reflects", sanityClass(!referenceZero, s),
          fmt::format("a refracted ray past the critical angle (1 - eta^2 sin^2 = {:.3g})", k2),
          s.value);
  }

  // Snell's law (refraction, eta from the listing) or the mirror law with
  // the true normal and the unit view ray (0, 0, -1): the listing's
  // direction may differ in length (the Cg tutorial's I is not normalised)
  // but not in direction.
  void physicsDirection(std::size_t k, const std::string& name, OutputRole role, const Sample& s) {
    const ListingPoint& p = (*draw.points)[k];
    const std::array<double, 3> I = {0, 0, -1};
    const std::array<double, 3>& n = p.trueNormal;
    const double cosine = -(I[0] * n[0] + I[1] * n[1] + I[2] * n[2]);
    std::vector<double> physical(3);
    if (role == OutputRole::Refracted) {
      const double eta = draw.etaOf(name);
      const double k2 = 1 - eta * eta * (1 - cosine * cosine);
      if (!(eta > 0) || k2 < 0) return;  // total internal reflection: no ray to compare
      for (int c = 0; c < 3; ++c) physical[c] = eta * I[c] + (eta * cosine - std::sqrt(k2)) * n[c];
    } else {
      for (int c = 0; c < 3; ++c) physical[c] = I[c] + 2 * cosine * n[c];
    }
    auto degreesOff = [&](const std::vector<double>& v) {
      const double l = length3(v) * length3(physical);
      const double d = (v[0] * physical[0] + v[1] * physical[1] + v[2] * physical[2]) / l;
      return std::acos(std::clamp(d, -1.0, 1.0)) / kDegree;
    };
    const double off = degreesOff(s.value);
    if (!(off > kDirectionBoundDegrees)) return;
    const bool referenceOff =
        !allZero(s.reference) && degreesOff(s.reference) > kDirectionBoundDegrees;
    add(k, name,
        role == OutputRole::Refracted ? "refracted_direction_error" : "reflected_direction_error",
        sanityClass(referenceOff, s),
        fmt::format("{:.3g} deg from the physical direction (bound {:.3g} deg, one environment "
                    "texel)",
                    off, kDirectionBoundDegrees),
        s.value);
  }

  // A diffraction listing's highlight divides by dot(N, H). Where that
  // goes to 0 the result stops depending on the surface in any stable
  // way: the spec's interval for it spans more than kIllConditionedWidth
  // (a tenth of the colour range), or it is not finite. The backends are
  // right (they stay in the interval), the method is not.
  void nearHalfVectorZero(std::size_t k, const std::string& name, const Sample& s) {
    const ListingPoint& p = (*draw.points)[k];
    double widest = 0;
    for (std::size_t c = 0; c < s.value.size(); ++c) {
      const double w = s.hi[c] - s.lo[c];
      widest = std::max(widest, std::isfinite(w) ? w : std::numeric_limits<double>::infinity());
    }
    if (s.finite() && widest <= kIllConditionedWidth) return;
    add(k, name, "diffraction_dot_NH_to_0",
        s.withinSpec() || s.undefined ? BreakClass::Method : BreakClass::Implementation,
        fmt::format("dot(N, H) = {:.3g}: the highlight divides by it; the spec allows results "
                    "{:.3g} apart here",
                    p.dotNH, widest),
        s.value);
  }

  // Front-facing grid points of one output, by angle.
  std::vector<std::size_t> frontSeries() const {
    std::vector<std::size_t> series;
    for (std::size_t k = 0; k < draw.points->size(); ++k)
      if ((*draw.points)[k].input == "grid") series.push_back(k);
    std::sort(series.begin(), series.end(), [&](std::size_t a, std::size_t b) {
      return (*draw.points)[a].angleDegrees < (*draw.points)[b].angleDegrees;
    });
    return series;
  }

  void seriesChecks(const OracleVarying& expected, const CapturedVarying& observed,
                    OutputRole role) {
    const std::vector<std::size_t> series = frontSeries();
    for (std::size_t m = 1; m < series.size(); ++m) {
      const Sample p = sampleAt(expected, observed, series[m - 1]);
      const Sample q = sampleAt(expected, observed, series[m]);
      if (!p.finite() || !q.finite()) continue;
      for (std::size_t c = 0; c < p.value.size(); ++c) {
        const double jump = std::abs(q.value[c] - p.value[c]);
        const double allowed = std::abs(q.reference[c] - p.reference[c]) + p.width(c) + q.width(c);
        if (jump <= allowed) continue;
        add(series[m], expected.name, "discontinuity",
            p.withinSpec() && q.withinSpec() ? BreakClass::Undefined : BreakClass::Implementation,
            fmt::format("component {} jumps {:.3g} from {:.7g} deg; the listing's own slope and "
                        "the intervals allow {:.3g}",
                        c, jump, (*draw.points)[series[m - 1]].angleDegrees, allowed),
            q.value);
        break;
      }
      if (role == OutputRole::Weight && q.value[0] < p.value[0] - p.width(0) - q.width(0))
        add(series[m], expected.name, "weight_falls_toward_grazing",
            sanityClass(q.reference[0] < p.reference[0], q),
            fmt::format("{:.6g} at {:.7g} deg after {:.6g} at {:.7g} deg", q.value[0],
                        (*draw.points)[series[m]].angleDegrees, p.value[0],
                        (*draw.points)[series[m - 1]].angleDegrees),
            q.value);
    }
    if (role == OutputRole::Weight) silhouette(expected, observed, series);
  }

  // A triangle across the silhouette, its vertices kSilhouetteSpacingDegrees
  // apart with the far one at grazing, shades its middle with the mean of
  // their weights: held against exact Fresnel at the middle.
  void silhouette(const OracleVarying& expected, const CapturedVarying& observed,
                  const std::vector<std::size_t>& series) {
    if (draw.eta <= 0) return;
    auto at = [&](double degrees) -> long {
      for (std::size_t k : series)
        if (std::abs((*draw.points)[k].angleDegrees - degrees) < 1e-9) return static_cast<long>(k);
      return -1;
    };
    const double near = 90 - kSilhouetteSpacingDegrees, middle = 90 - kSilhouetteSpacingDegrees / 2;
    const long a = at(near), b = at(90), mid = at(middle);
    if (a < 0 || b < 0 || mid < 0) return;
    const Sample sa = sampleAt(expected, observed, static_cast<std::size_t>(a));
    const Sample sb = sampleAt(expected, observed, static_cast<std::size_t>(b));
    const Sample sm = sampleAt(expected, observed, static_cast<std::size_t>(mid));
    if (!sa.finite() || !sb.finite() || !sm.finite()) return;
    const double mean = (sa.value[0] + sb.value[0]) / 2;
    const double exact = methodSample("exact", draw.eta, middle).exact;
    if (std::abs(mean - exact) <= kMethodErrorBound) return;
    add(static_cast<std::size_t>(mid), expected.name, "per_vertex_at_silhouette",
        BreakClass::Method,
        fmt::format("vertex weights {:.4f} ({:.4g} deg) and {:.4f} (90 deg) give {:.4f} at the "
                    "middle; exact Fresnel {:.4f}, the listing per fragment {:.4f}",
                    sa.value[0], near, sb.value[0], mean, exact, sm.value[0]),
        {mean});
  }
};

}  // namespace

OutputRole outputRole(const std::string& name, int components) {
  const std::string n = lower(name);
  if (components >= 3 && (n.rfind("refract", 0) == 0 || n == "t")) return OutputRole::Refracted;
  if (components >= 3 && n.rfind("reflect", 0) == 0) return OutputRole::Reflected;
  if (components == 1) return OutputRole::Weight;
  return OutputRole::Other;
}

std::vector<ListingBreak> classifyListingDraw(const ListingDrawView& draw,
                                              const ListingBackendView& backend) {
  DrawClassifier classifier{draw, backend, {}};
  auto whole = [&](std::string kind, std::string detail) {
    classifier.breaks.push_back({draw.listing,
                                 "",
                                 backend.backend,
                                 draw.frame,
                                 "draw",
                                 draw.eta,
                                 0,
                                 std::move(kind),
                                 BreakClass::Implementation,
                                 std::move(detail),
                                 {}});
  };
  if (!backend.answered) {
    whole(backend.timedOut ? "timeout" : "crash", backend.problem);
    return classifier.breaks;
  }
  if (!backend.problem.empty()) {
    whole("not_drawn", backend.problem);
    return classifier.breaks;
  }
  if (!backend.compiled) {
    whole("compile_error", "the listing did not compile at this eta: " + backend.log);
    return classifier.breaks;
  }
  const std::vector<OracleVarying>& expected = *backend.expected;
  const std::vector<CapturedVarying>& observed = *backend.observed;
  for (std::size_t o = 0; o < expected.size() && o < observed.size(); ++o) {
    const OutputRole role = outputRole(expected[o].name, expected[o].components);
    for (std::size_t k = 0; k < draw.points->size(); ++k) {
      const Sample s = sampleAt(expected[o], observed[o], k);
      classifier.specChecks(k, expected[o].name, s);
      const ListingPoint& p = (*draw.points)[k];
      if (p.input == "dot(N,H)->0") classifier.nearHalfVectorZero(k, expected[o].name, s);
      if (!s.finite() || (p.input != "grid" && p.input != "back-face")) continue;
      if (role == OutputRole::Weight) classifier.weightChecks(k, expected[o].name, s);
      if (role == OutputRole::Refracted || role == OutputRole::Reflected)
        classifier.directionChecks(k, expected[o].name, role, s);
    }
    classifier.seriesChecks(expected[o], observed[o], role);
  }
  return classifier.breaks;
}

std::vector<ListingBreak> listingDisagreements(const ListingDrawView& draw,
                                               const ListingBackendView& a,
                                               const ListingBackendView& b) {
  std::vector<ListingBreak> breaks;
  if (!a.answered || !b.answered || !a.problem.empty() || !b.problem.empty() || !a.compiled ||
      !b.compiled)
    return breaks;
  for (std::size_t o = 0; o < a.expected->size() && o < a.observed->size(); ++o)
    for (std::size_t k = 0; k < draw.points->size(); ++k) {
      const Sample x = sampleAt((*a.expected)[o], (*a.observed)[o], k);
      const Sample y = sampleAt((*b.expected)[o], (*b.observed)[o], k);
      std::string why;
      for (std::size_t c = 0; c < x.value.size() && why.empty(); ++c) {
        const bool nanX = std::isnan(x.value[c]), nanY = std::isnan(y.value[c]);
        if (nanX != nanY)
          why = fmt::format("component {}: NaN on one side only", c);
        else if (!nanX && x.value[c] != y.value[c] &&
                 !(std::abs(x.value[c] - y.value[c]) <= std::max(x.width(c), y.width(c))))
          why = fmt::format("component {}: {:.9g} against {:.9g}", c, x.value[c], y.value[c]);
      }
      if (why.empty()) continue;
      const ListingPoint& p = (*draw.points)[k];
      const bool open = !inputFinite(p) || x.undefined || y.undefined;
      const bool implementation = (!x.withinSpec() || !y.withinSpec()) && !open;
      std::vector<double> value = x.value;
      value.insert(value.end(), y.value.begin(), y.value.end());
      breaks.push_back({draw.listing, (*a.expected)[o].name, a.backend + "|" + b.backend,
                        draw.frame, p.input, draw.eta, p.angleDegrees, "backend_disagreement",
                        implementation ? BreakClass::Implementation : BreakClass::Undefined, why,
                        std::move(value)});
    }
  return breaks;
}

std::vector<ListingCriticalAngle> listingCriticalAngles(const ListingDrawView& draw,
                                                        const ListingBackendView& backend) {
  std::vector<ListingCriticalAngle> found;
  if (!backend.answered || !backend.problem.empty() || !backend.compiled) return found;
  for (std::size_t o = 0; o < backend.expected->size() && o < backend.observed->size(); ++o) {
    const OracleVarying& expected = (*backend.expected)[o];
    if (outputRole(expected.name, expected.components) != OutputRole::Refracted) continue;
    const double eta = draw.etaOf(expected.name);
    if (!(eta > 1)) continue;
    std::vector<std::size_t> series;
    for (std::size_t k = 0; k < draw.points->size(); ++k)
      if ((*draw.points)[k].input == "grid" && (*draw.points)[k].angleDegrees < 90)
        series.push_back(k);
    std::sort(series.begin(), series.end(), [&](std::size_t a, std::size_t b) {
      return (*draw.points)[a].angleDegrees < (*draw.points)[b].angleDegrees;
    });
    ListingCriticalAngle c{draw.listing, expected.name, backend.backend,
                           draw.frame,   eta,           std::asin(1 / eta) / kDegree};
    for (std::size_t m = 1; m < series.size() && !c.found; ++m) {
      const Sample p = sampleAt(expected, (*backend.observed)[o], series[m - 1]);
      const Sample q = sampleAt(expected, (*backend.observed)[o], series[m]);
      if (!allZero(p.value) && allZero(q.value)) {
        c.found = true;
        c.lastRefractedDegrees = (*draw.points)[series[m - 1]].angleDegrees;
        c.firstZeroDegrees = (*draw.points)[series[m]].angleDegrees;
        c.foundDegrees = (c.lastRefractedDegrees + c.firstZeroDegrees) / 2;
      }
    }
    found.push_back(c);
  }
  return found;
}

}  // namespace snell::sweep
