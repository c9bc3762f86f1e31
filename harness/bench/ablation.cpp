#include "bench/ablation.h"

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "bench/dispersion_reference_image.h"
#include "bench/fresnel_reference_image.h"
#include "bench/ladder_checks.h"
#include "bench/sphere_trace_image.h"
#include "core/atomic_file.h"
#include "runner/json_fields.h"

namespace snell::bench {
namespace {

constexpr double kIndex = 1.5;

AblationRow row(std::string effect, const ReferenceImage& with, const ReferenceImage& without) {
  AblationRow r{std::move(effect), imageError(with.color, without.color, without.covered), false};
  r.visible = r.change.rms > errorNoise("rms") || r.change.deMean > errorNoise("de_mean") ||
              r.change.deP95 > errorNoise("de_p95");
  return r;
}

nlohmann::json rowsJson(const std::vector<AblationRow>& rows) {
  nlohmann::json out = nlohmann::json::array();
  for (const AblationRow& r : rows)
    out.push_back({{"effect", r.effect},
                   {"rms", r.change.rms},
                   {"max", r.change.max},
                   {"de_mean", r.change.deMean},
                   {"de_p95", r.change.deP95},
                   {"visible", r.visible}});
  return out;
}

}  // namespace

AblationTable ablationTable(const Scene& scene, int size, int internalHits, int wavelengths) {
  AblationTable table;
  table.size = size;
  ReferenceImage previous = fresnelReferenceImage(scene, 1.0 / kIndex, size, size);
  for (int hits = 1; hits <= internalHits; ++hits) {
    ReferenceImage next = sphereTraceImage(scene, kIndex, hits, size);
    table.geometric.push_back(row(hits == 1 ? std::string("second interface")
                                            : fmt::format("internal reflection {}", hits - 1),
                                  next, previous));
    previous = std::move(next);
    if (!table.geometric.back().visible) break;  // the reference stops here
  }
  previous = dispersionReferenceImage(scene, physics::nBk7(), 4, size, size);
  for (int n = 8; n <= wavelengths; n *= 2) {
    ReferenceImage next = dispersionReferenceImage(scene, physics::nBk7(), n, size, size);
    table.spectral.push_back(row(fmt::format("wavelengths {} -> {}", n / 2, n), next, previous));
    previous = std::move(next);
  }
  return table;
}

std::string ablationText(const AblationTable& table) {
  std::string out = fmt::format(
      "\nablation of the physics reference ({}px): each row adds one effect to the row above; "
      "the change it makes to the picture\n  {:<28} {:>9} {:>9} {:>10} {:>10}  {}\n",
      table.size, "effect", "rms", "max", "dE00 mean", "dE00 p95", "visible");
  const auto lines = [&](const char* heading, const std::vector<AblationRow>& rows) {
    out += fmt::format("  {}\n", heading);
    for (const AblationRow& r : rows)
      out += fmt::format("  {:<28} {:>9.2e} {:>9.2e} {:>10.4f} {:>10.4f}  {}\n", r.effect,
                         r.change.rms, r.change.max, r.change.deMean, r.change.deP95,
                         r.visible ? "yes" : "no");
  };
  lines("geometry (index 1.5; from the first interface only):", table.geometric);
  lines("spectrum (N-BK7; from 4 wavelengths):", table.spectral);
  out += fmt::format(
      "  visible: a change above the noise in rms ({:.2g}), dE00 mean or p95 ({:.2g})\n",
      errorNoise("rms"), errorNoise("de_mean"));
  return out;
}

void writeAblationJson(const AblationTable& table, const std::filesystem::path& path) {
  const nlohmann::json doc{{"size", table.size},
                           {"noise", {{"rms", errorNoise("rms")}, {"de", errorNoise("de_mean")}}},
                           {"geometric", rowsJson(table.geometric)},
                           {"spectral", rowsJson(table.spectral)}};
  writeFileAtomically(path, jsonText(doc, 2) + "\n");
}

}  // namespace snell::bench
