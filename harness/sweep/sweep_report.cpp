#include "sweep/sweep_report.h"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "core/atomic_file.h"
#include "runner/json_fields.h"
#include "sweep/listing_report.h"
#include "sweep/sweep_summary.h"

namespace snell::sweep {
namespace {

using nlohmann::json;

json number(double x) {
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  return x;
}

json numbers(const std::vector<double>& v) {
  json out = json::array();
  for (double x : v) out.push_back(number(x));
  return out;
}

json floats(const std::vector<float>& v) {
  json out = json::array();
  for (float x : v) out.push_back(number(x));
  return out;
}

json builtinBreak(const SweepResult& result, const Break& b) {
  const SweepPoint& p = result.points[b.point];
  json out = {
      {"function", b.function},      {"backend", b.backend},  {"input", p.input},
      {"angle_deg", p.angleDegrees}, {"I", floats(p.call.I)}, {"N", floats(p.call.N)},
      {"value", numbers(b.value)},   {"kind", b.kind},        {"class", breakClassName(b.cls)},
      {"detail", b.detail}};
  if (p.call.fn == "refract") {
    out["eta"] = p.eta;
    out["eta_fp32"] = number(p.call.eta);
  }
  return out;
}

json methodBreak(const SweepResult& result, const Break& b) {
  const MethodSample& s = result.methodSamples[b.point];
  return {{"method", s.method},
          {"backend", b.backend},
          {"eta", s.eta},
          {"n1", s.n1},
          {"n2", s.n2},
          {"angle_deg", s.angleDegrees},
          {"value", s.value},
          {"exact", s.exact},
          {"error", s.error()},
          {"kind", b.kind},
          {"class", breakClassName(b.cls)},
          {"detail", b.detail}};
}

}  // namespace

void writeSweepJson(const SweepResult& result, const std::filesystem::path& path) {
  json out;
  out["wall_seconds"] = result.wallSeconds;
  out["points"] = result.points.size();
  out["etas"] = result.grid.etas;
  out["angles_deg"] = result.grid.angles;
  out["critical_offsets_rad"] = result.grid.criticalOffsets;
  out["method_error_bound"] = kMethodErrorBound;
  json backends = json::array();
  for (const BackendSweep& s : result.sweeps) {
    std::size_t answered = 0;
    for (const Observation& o : s.points) answered += o.answered;
    backends.push_back({{"name", s.backend}, {"renderer", s.renderer}, {"answered", answered}});
  }
  out["backends"] = backends;
  json critical = json::array();
  for (const CriticalAngle& c : result.criticalAngles)
    critical.push_back({{"backend", c.backend},
                        {"eta", c.eta},
                        {"closed_form_deg", c.closedFormDegrees},
                        {"found_deg", number(c.foundDegrees)},
                        {"last_refracted_deg", c.lastRefractedDegrees},
                        {"first_zero_deg", number(c.firstZeroDegrees)},
                        {"resolution_deg", number(c.resolutionDegrees)},
                        {"spec_band_deg", c.specBandDegrees},
                        {"input_rounding_deg", c.inputRoundingDegrees},
                        {"wrong_side_points", c.wrongSide},
                        {"agrees", c.agrees}});
  out["critical_angles"] = critical;
  json summary = json::array();
  for (const BreakGroup& g : groupBreaks(result))
    summary.push_back({{"function", g.function},
                       {"backend", g.backend},
                       {"input", g.input},
                       {"kind", g.kind},
                       {"class", g.cls},
                       {"count", g.count},
                       {"angle_deg", {g.angleMin, g.angleMax}},
                       {"eta", {g.etaMin, g.etaMax}}});
  out["summary"] = summary;
  json breaks = json::array();
  for (const Break& b : result.breaks) breaks.push_back(builtinBreak(result, b));
  for (const Break& b : result.methodBreaks) breaks.push_back(methodBreak(result, b));
  out["breaks"] = breaks;
  if (result.listingsSwept) out["listings"] = listingSweepJson(result.listings);
  writeFileAtomically(path, jsonText(out, 1) + "\n");
}

void printSweepTable(const SweepResult& result, std::FILE* file) {
  fmt::print(file, "{:<19} {:<12} {:<21} {:<22} {:<14} {:>6}  {:<19} {}\n", "function/method",
             "backend", "input", "kind", "class", "points", "angle (deg)", "eta");
  for (const BreakGroup& g : groupBreaks(result)) {
    const std::string angles = g.angleMin == g.angleMax
                                   ? fmt::format("{:.6g}", g.angleMin)
                                   : fmt::format("{:.6g}-{:.6g}", g.angleMin, g.angleMax);
    const std::string etas = g.etaMin == g.etaMax
                                 ? fmt::format("{:.4g}", g.etaMin)
                                 : fmt::format("{:.4g}-{:.4g}", g.etaMin, g.etaMax);
    fmt::print(file, "{:<19} {:<12} {:<21} {:<22} {:<14} {:>6}  {:<19} {}\n", g.function, g.backend,
               g.input, g.kind, g.cls, g.count, angles, etas);
  }
  fmt::print(file,
             "\ncritical angles (refract switches to the zero vector; closed form asin(1/eta)):\n");
  fmt::print(file, "{:<8} {:>8} {:>13} {:>13} {:>11} {:>11} {:>11} {:>11} {:>6}  {}\n", "backend",
             "eta", "closed form", "found", "difference", "resolution", "spec band", "fp32 input",
             "wrong", "agrees");
  for (const CriticalAngle& c : result.criticalAngles)
    fmt::print(
        file,
        "{:<8} {:>8.5g} {:>13.7f} {:>13.7f} {:>11.2e} {:>11.2e} {:>11.2e} {:>11.2e} {:>6}  {}\n",
        c.backend, c.eta, c.closedFormDegrees, c.foundDegrees, c.foundDegrees - c.closedFormDegrees,
        c.resolutionDegrees, c.specBandDegrees, c.inputRoundingDegrees, c.wrongSide,
        c.agrees ? "yes" : "NO");
  if (result.listingsSwept) printListingTable(result.listings, file);
}

}  // namespace snell::sweep
