#include "report/sweep_findings.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <tuple>

#include "core/errors.h"

namespace snell {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr std::size_t kFirstPoints = 3;

// Letters, digits, '.', '-' and '_' only: a gnuplot string and a file name.
std::string safe(const std::string& text) {
  std::string out;
  for (char c : text)
    out +=
        (std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '_') ? c : '-';
  return out;
}

// The JSON writes NaN and infinities as strings.
std::string valueText(const json& v) {
  if (v.is_string()) return v.get<std::string>();
  return fmt::format("{:.6g}", v.get<double>());
}

std::string pointText(const json& b) {
  std::string value;
  for (const json& x : b.at("value")) value += (value.empty() ? "" : ", ") + valueText(x);
  const double eta = b.at("eta").get<double>();
  return fmt::format("{:.7g} deg, {}{}{}: {} ({}{})", b.at("angle_deg").get<double>(),
                     eta > 0 ? fmt::format("eta {:.5g}", eta) : "no eta",
                     b.at("frame").get<std::string>() == "unit" ? "" : ", stretched",
                     b.at("input").get<std::string>() == "grid"
                         ? ""
                         : ", input " + b.at("input").get<std::string>(),
                     b.at("kind").get<std::string>(), b.at("detail").get<std::string>(),
                     value.empty() ? "" : "; value (" + value + ")");
}

// How bad a break is, for picking the worst of a group: a non-finite value
// first, then the measure each kind words into its detail: the number after
// the first "= " ("1 - eta^2 sin^2 = 0.93"), else the first number (slack,
// degrees off, the jump, the cosine to the normal). Larger is worse; for
// the few kinds where it is not (dot(N, H) toward 0) the worst is a guess.
double severity(const json& b) {
  for (const json& x : b.at("value"))
    if (x.is_string()) return INFINITY;
  static const std::regex number(R"([-+]?[0-9]*\.?[0-9]+(?:[eE][-+]?[0-9]+)?)");
  const std::string detail = b.at("detail").get<std::string>();
  const std::size_t equals = detail.find("= ");
  const std::string measured = equals == std::string::npos ? detail : detail.substr(equals);
  std::smatch m;
  if (!std::regex_search(measured, m, number)) return 0;
  return std::abs(std::stod(m.str()));
}

void addChart(std::vector<SweepChart>& charts, const fs::path& dir, const std::string& stem,
              const std::string& caption) {
  if (fs::exists(dir / (stem + ".png"))) charts.push_back({caption, dir / (stem + ".png")});
}

SweepFindings read(const fs::path& dir, const json& root) {
  SweepFindings findings;
  findings.dir = dir;
  if (!root.contains("listings"))
    throw UsageError(fmt::format(
        "{}: no listings in this sweep: run `snell sweep --listings '*' --out {}` first",
        (dir / "sweep.json").string(), dir.string()));
  const json& listings = root.at("listings");
  for (const json& id : listings.at("swept")) findings.swept.push_back(id.get<std::string>());
  for (const json& n : listings.at("not_swept"))
    findings.notSwept[n.at("listing").get<std::string>()] = n.at("why").get<std::string>();
  using Key = std::tuple<std::string, std::string, std::string>;  // listing, backend, class
  std::map<Key, SweepGroup> groups;
  std::map<Key, std::map<std::string, std::size_t>> kinds;
  std::map<Key, double> worst;
  for (const json& b : listings.at("breaks")) {
    const Key key{b.at("listing").get<std::string>(), b.at("backend").get<std::string>(),
                  b.at("class").get<std::string>()};
    SweepGroup& g = groups[key];
    g.backend = std::get<1>(key);
    g.cls = std::get<2>(key);
    ++g.count;
    ++kinds[key][b.at("kind").get<std::string>()];
    const std::string text = pointText(b);
    if (g.first.size() < kFirstPoints) g.first.push_back({text});
    const double s = severity(b);
    if (g.count == 1 || s > worst[key]) {
      worst[key] = s;
      g.worst = {text};
    }
  }
  for (auto& [key, g] : groups) {
    for (const auto& [kind, n] : kinds[key])
      g.kinds += fmt::format("{}{} {}", g.kinds.empty() ? "" : ", ", n, kind);
    findings.groups[std::get<0>(key)].push_back(std::move(g));
  }
  addChart(findings.charts, dir, "sweep-map-refract",
           "refract(): where each backend breaks, and why");
  addChart(findings.charts, dir, "sweep-map-methods", "Fresnel methods: where each breaks");
  addChart(findings.charts, dir, "sweep-method-error",
           "Fresnel methods: error against exact Fresnel");
  addChart(findings.charts, dir, "sweep-refract-slack", "refract(): slack against angle");
  addChart(findings.charts, dir, "sweep-reflect-slack", "reflect(): slack against angle");
  return findings;
}

}  // namespace

std::string listingMapStem(const std::string& listing, const std::string& backend) {
  return "sweep-map-listing-" + safe(listing) + "-" + safe(backend);
}

SweepFindings readSweepFindings(const fs::path& dir) {
  const fs::path file = dir / "sweep.json";
  std::ifstream in(file, std::ios::binary);
  if (!in)
    throw UsageError(fmt::format("{}: cannot read it: --sweep names a `snell sweep --out` folder",
                                 file.string()));
  std::stringstream text;
  text << in.rdbuf();
  try {
    return read(dir, json::parse(text.str()));
  } catch (const json::exception& e) {
    // nlohmann's message gives the line and column of a syntax error, or
    // the key or type that is wrong.
    throw UsageError(
        fmt::format("{}: not a sweep's JSON ({}): write it again with `snell sweep --out {}`",
                    file.string(), readableError(e), dir.string()));
  }
}

ListingFindings findingsFor(const SweepFindings& findings, const std::string& listing) {
  ListingFindings out;
  if (std::find(findings.swept.begin(), findings.swept.end(), listing) == findings.swept.end()) {
    const auto it = findings.notSwept.find(listing);
    out.why = it != findings.notSwept.end()
                  ? "Not swept: " + it->second
                  : "This sweep did not cover this listing (`snell sweep --listings`).";
    return out;
  }
  out.covered = true;
  const auto it = findings.groups.find(listing);
  if (it == findings.groups.end()) return out;
  out.groups = it->second;
  std::vector<std::string> backends;
  for (const SweepGroup& g : out.groups)
    if (std::find(backends.begin(), backends.end(), g.backend) == backends.end())
      backends.push_back(g.backend);
  for (const std::string& backend : backends)
    addChart(out.charts, findings.dir, listingMapStem(listing, backend),
             fmt::format("{} on {}: breaks over angle and eta, colour by class", listing, backend));
  return out;
}

}  // namespace snell
