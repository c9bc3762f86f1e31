#include "sweep/sweep_classify.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace snell::sweep {
namespace {

bool allZero(const std::vector<double>& v) {
  return std::all_of(v.begin(), v.end(), [](double x) { return x == 0.0; });
}

bool anyNonFinite(const std::vector<double>& v) {
  return std::any_of(v.begin(), v.end(), [](double x) { return !std::isfinite(x); });
}

// Where the spec itself gives no answer, a break is the spec's, not the backend's.
bool specOpen(const SweepPoint& point, const Observation& o) {
  return !inputsFinite(point) || o.undefined;
}

Break makeBreak(const SweepPoint& point, std::size_t index, const std::string& backend,
                std::string kind, BreakClass cls, std::string detail, std::vector<double> value) {
  return {point.call.fn, backend, index, std::move(kind), cls, std::move(detail), std::move(value)};
}

double width(const Observation& o, std::size_t c) {
  const double w = o.hi[c] - o.lo[c];
  return std::isfinite(w) ? w : 0.0;
}

}  // namespace

const char* breakClassName(BreakClass c) {
  switch (c) {
    case BreakClass::Implementation:
      return "implementation";
    case BreakClass::Undefined:
      return "undefined";
    case BreakClass::Method:
      return "method";
  }
  return "?";
}

bool inputsFinite(const SweepPoint& point) {
  auto finite = [](const std::vector<float>& v) {
    return std::all_of(v.begin(), v.end(), [](float x) { return std::isfinite(x); });
  };
  return finite(point.call.I) && finite(point.call.N) &&
         (point.call.fn != "refract" || std::isfinite(point.call.eta));
}

std::vector<Break> classifyPoint(const SweepPoint& point, std::size_t index, const Observation& o,
                                 const std::string& backend) {
  std::vector<Break> breaks;
  if (!o.answered) {
    // A child cut off at --timeout did not crash: the kind says which, so
    // a limit set too short reads as what it is.
    breaks.push_back(makeBreak(point, index, backend, o.timedOut ? "timeout" : "crash",
                               BreakClass::Implementation, o.problem, {}));
    return breaks;
  }
  const bool open = specOpen(point, o);
  if (anyNonFinite(o.value)) {
    // Allowed where the input is not finite, the oracle leaves a component
    // open, or the interval itself reaches infinity (an overflow).
    const bool allowed = open || o.withinSpec;
    const char* why = !inputsFinite(point) ? "a NaN or infinite input"
                      : o.undefined        ? "the spec leaves a component open here"
                      : o.withinSpec       ? "within the interval: an overflow the spec allows"
                                           : "finite inputs, outside the spec";
    breaks.push_back(makeBreak(point, index, backend, "nan_or_inf_output",
                               allowed ? BreakClass::Undefined : BreakClass::Implementation, why,
                               o.value));
  }
  if (!o.withinSpec && !anyNonFinite(o.value)) {
    breaks.push_back(makeBreak(point, index, backend, "outside_spec",
                               open ? BreakClass::Undefined : BreakClass::Implementation,
                               fmt::format("slack {:.3g}", o.slack), o.value));
  }
  if (point.call.fn == "refract" && allZero(o.value)) {
    breaks.push_back(makeBreak(point, index, backend, "zero_vector_direction",
                               BreakClass::Undefined,
                               "refract() gave the zero vector (total internal reflection or a "
                               "zero input): undefined as a direction (normalize, cube lookup)",
                               o.value));
  }
  return breaks;
}

std::vector<Break> disagreements(const std::vector<SweepPoint>& points, const BackendSweep& a,
                                 const BackendSweep& b) {
  std::vector<Break> breaks;
  const std::string pair = a.backend + "|" + b.backend;
  for (std::size_t k = 0; k < points.size(); ++k) {
    const Observation& x = a.points[k];
    const Observation& y = b.points[k];
    if (!x.answered || !y.answered) continue;  // the crash is recorded already
    std::string why;
    for (std::size_t c = 0; c < x.value.size() && why.empty(); ++c) {
      const bool nanX = std::isnan(x.value[c]), nanY = std::isnan(y.value[c]);
      if (nanX != nanY) {
        why = fmt::format("component {}: NaN on one side only", c);
      } else if (!nanX && x.value[c] != y.value[c]) {
        const double difference = std::abs(x.value[c] - y.value[c]);
        if (!(difference <= std::max(width(x, c), width(y, c))))
          why = fmt::format("component {}: {:.9g} against {:.9g}", c, x.value[c], y.value[c]);
      }
    }
    if (why.empty()) continue;
    const bool implementation = (!x.withinSpec || !y.withinSpec) && !specOpen(points[k], x);
    Break d = makeBreak(points[k], k, pair, "backend_disagreement",
                        implementation ? BreakClass::Implementation : BreakClass::Undefined, why,
                        x.value);
    d.value.insert(d.value.end(), y.value.begin(), y.value.end());
    breaks.push_back(std::move(d));
  }
  return breaks;
}

std::vector<Break> discontinuities(const std::vector<SweepPoint>& points,
                                   const BackendSweep& sweep) {
  std::map<std::pair<std::string, double>, std::vector<std::size_t>> series;
  for (std::size_t k = 0; k < points.size(); ++k)
    if (points[k].input == "grid") series[{points[k].call.fn, points[k].eta}].push_back(k);
  std::vector<Break> breaks;
  for (auto& [key, members] : series) {
    std::sort(members.begin(), members.end(), [&](std::size_t a, std::size_t b) {
      return points[a].angleDegrees < points[b].angleDegrees;
    });
    for (std::size_t m = 1; m < members.size(); ++m) {
      const std::size_t i = members[m - 1], j = members[m];
      const Observation& p = sweep.points[i];
      const Observation& q = sweep.points[j];
      if (!p.answered || !q.answered || anyNonFinite(p.value) || anyNonFinite(q.value)) continue;
      for (std::size_t c = 0; c < p.value.size(); ++c) {
        const double jump = std::abs(q.value[c] - p.value[c]);
        const double allowed = std::abs(q.exact[c] - p.exact[c]) + width(p, c) + width(q, c);
        if (jump <= allowed) continue;
        const bool implementation = !p.withinSpec || !q.withinSpec;
        breaks.push_back(makeBreak(
            points[j], j, sweep.backend, "discontinuity",
            implementation ? BreakClass::Implementation : BreakClass::Undefined,
            fmt::format("component {} jumps {:.3g} from {:.7g} deg, the exact slope and the "
                        "intervals allow {:.3g}",
                        c, jump, points[i].angleDegrees, allowed),
            q.value));
        break;
      }
    }
  }
  return breaks;
}

std::vector<Break> classifySweep(const std::vector<SweepPoint>& points,
                                 const std::vector<BackendSweep>& sweeps) {
  std::vector<Break> breaks;
  auto append = [&](std::vector<Break> more) {
    breaks.insert(breaks.end(), std::make_move_iterator(more.begin()),
                  std::make_move_iterator(more.end()));
  };
  for (const BackendSweep& sweep : sweeps) {
    for (std::size_t k = 0; k < points.size(); ++k)
      append(classifyPoint(points[k], k, sweep.points[k], sweep.backend));
    append(discontinuities(points, sweep));
  }
  for (std::size_t a = 0; a < sweeps.size(); ++a)
    for (std::size_t b = a + 1; b < sweeps.size(); ++b)
      if (sweeps[a].backend != "oracle" && sweeps[b].backend != "oracle")
        append(disagreements(points, sweeps[a], sweeps[b]));
  return breaks;
}

}  // namespace snell::sweep
