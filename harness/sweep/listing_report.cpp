#include "sweep/listing_report.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

namespace snell::sweep {
namespace {

using nlohmann::json;

json number(double x) {
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  return x;
}

std::string range(double lo, double hi, int digits) {
  return lo == hi ? fmt::format("{:.{}g}", lo, digits)
                  : fmt::format("{:.{}g}-{:.{}g}", lo, digits, hi, digits);
}

}  // namespace

std::vector<ListingBreakGroup> groupListingBreaks(const std::vector<ListingBreak>& breaks) {
  using Key = std::tuple<std::string, std::string, std::string, std::string, std::string,
                         std::string, std::string>;
  std::map<Key, ListingBreakGroup> groups;
  for (const ListingBreak& b : breaks) {
    const std::string cls = breakClassName(b.cls);
    const Key key{b.listing, b.backend, b.output, b.frame, b.input, b.kind, cls};
    auto [it, fresh] = groups.try_emplace(key);
    ListingBreakGroup& g = it->second;
    if (fresh) {
      g = {b.listing, b.backend, b.output,       b.frame,        b.input, b.kind,
           cls,       0,         b.angleDegrees, b.angleDegrees, b.eta,   b.eta};
    }
    ++g.count;
    g.angleMin = std::min(g.angleMin, b.angleDegrees);
    g.angleMax = std::max(g.angleMax, b.angleDegrees);
    g.etaMin = std::min(g.etaMin, b.eta);
    g.etaMax = std::max(g.etaMax, b.eta);
  }
  std::vector<ListingBreakGroup> out;
  for (auto& [key, g] : groups) out.push_back(g);
  return out;
}

json listingSweepJson(const ListingSweepResult& result) {
  json out;
  out["wall_seconds"] = result.wallSeconds;
  out["draws"] = result.draws;
  out["vertices"] = result.vertices;
  out["swept"] = result.swept;
  json notSwept = json::array(), notes = json::array();
  for (const ListingNote& n : result.notSwept)
    notSwept.push_back({{"listing", n.listing}, {"why", n.note}});
  for (const ListingNote& n : result.notes)
    notes.push_back({{"listing", n.listing}, {"note", n.note}});
  out["not_swept"] = notSwept;
  out["notes"] = notes;
  json critical = json::array();
  for (const ListingCriticalAngle& c : result.criticalAngles)
    critical.push_back({{"listing", c.listing},
                        {"output", c.output},
                        {"backend", c.backend},
                        {"frame", c.frame},
                        {"eta", c.eta},
                        {"closed_form_deg", c.closedFormDegrees},
                        {"found", c.found},
                        {"found_deg", c.foundDegrees},
                        {"last_refracted_deg", c.lastRefractedDegrees},
                        {"first_zero_deg", c.firstZeroDegrees}});
  out["critical_angles"] = critical;
  json summary = json::array();
  for (const ListingBreakGroup& g : groupListingBreaks(result.breaks))
    summary.push_back({{"listing", g.listing},
                       {"backend", g.backend},
                       {"output", g.output},
                       {"frame", g.frame},
                       {"input", g.input},
                       {"kind", g.kind},
                       {"class", g.cls},
                       {"count", g.count},
                       {"angle_deg", {g.angleMin, g.angleMax}},
                       {"eta", {g.etaMin, g.etaMax}}});
  out["summary"] = summary;
  json breaks = json::array();
  for (const ListingBreak& b : result.breaks) {
    json value = json::array();
    for (double x : b.value) value.push_back(number(x));
    breaks.push_back({{"listing", b.listing},
                      {"output", b.output},
                      {"backend", b.backend},
                      {"frame", b.frame},
                      {"input", b.input},
                      {"eta", b.eta},
                      {"angle_deg", b.angleDegrees},
                      {"kind", b.kind},
                      {"class", breakClassName(b.cls)},
                      {"detail", b.detail},
                      {"value", value}});
  }
  out["breaks"] = breaks;
  return out;
}

void printListingTable(const ListingSweepResult& result, std::FILE* file) {
  fmt::print(file, "\nlistings: {} swept ({} draws, {} vertices per backend), {} not swept\n",
             result.swept.size(), result.draws, result.vertices, result.notSwept.size());
  for (const ListingNote& n : result.notSwept)
    fmt::print(file, "  not swept: {}: {}\n", n.listing, n.note);
  for (const ListingNote& n : result.notes) fmt::print(file, "  note: {}: {}\n", n.listing, n.note);
  fmt::print(file, "{:<44} {:<8} {:<9} {:<9} {:<20} {:<30} {:<14} {:>6}  {:<17} {}\n", "listing",
             "backend", "output", "frame", "input", "kind", "class", "points", "angle (deg)",
             "eta");
  for (const ListingBreakGroup& g : groupListingBreaks(result.breaks))
    fmt::print(file, "{:<44} {:<8} {:<9} {:<9} {:<20} {:<30} {:<14} {:>6}  {:<17} {}\n", g.listing,
               g.backend, g.output, g.frame, g.input, g.kind, g.cls, g.count,
               range(g.angleMin, g.angleMax, 6),
               // A listing with no eta (diffraction) is drawn at eta 0.
               g.etaMax > 0 ? range(g.etaMin, g.etaMax, 4) : std::string("-"));
  fmt::print(file,
             "\nlistings' total internal reflection (a refracted output turns to zero), unit "
             "frame, as published and eta > 1; the closed form is asin(1/eta) of the decimal "
             "eta,\nwhich the listing's fp32 eta and vertex can move by about (tan + 1/tan) "
             "2^-24 radians (3.4e-5 degrees at eta 1.005, 6.9e-6 at 1.5):\n");
  fmt::print(file, "{:<44} {:<9} {:<8} {:>8} {:>12} {:>12} {:>12}\n", "listing", "output",
             "backend", "eta", "closed form", "found", "resolution");
  // Each listing's outputs and etas in order, the backends side by side
  // (the draws come eta by eta, so one output's rows were split by the
  // other outputs').
  std::vector<ListingCriticalAngle> rows = result.criticalAngles;
  std::stable_sort(rows.begin(), rows.end(),
                   [](const ListingCriticalAngle& a, const ListingCriticalAngle& b) {
                     return std::tie(a.listing, a.output, a.eta, a.backend) <
                            std::tie(b.listing, b.output, b.eta, b.backend);
                   });
  for (const ListingCriticalAngle& c : rows) {
    if (c.frame != "unit") continue;
    if (!c.found)
      fmt::print(file, "{:<44} {:<9} {:<8} {:>8.5g} {:>12.6f} {:>12} {:>12}\n", c.listing, c.output,
                 c.backend, c.eta, c.closedFormDegrees, "none", "-");
    else
      fmt::print(file, "{:<44} {:<9} {:<8} {:>8.5g} {:>12.6f} {:>12.6f} {:>12.2e}\n", c.listing,
                 c.output, c.backend, c.eta, c.closedFormDegrees, c.foundDegrees,
                 c.firstZeroDegrees - c.lastRefractedDegrees);
  }
}

}  // namespace snell::sweep
