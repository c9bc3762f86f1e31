#include "bench/wavelength_chart.h"

#include <fmt/format.h>

#include <fstream>
#include <set>

#include "bench/bench_chart.h"
#include "report/gnuplot_batch.h"

namespace snell::bench {
namespace {

// The wavelengths a method samples: its `Wavelengths`, 3 for one index per
// colour channel, 0 for neither.
double wavelengthCount(const BenchRecord& r) {
  if (const auto n = r.parameters.find("Wavelengths"); n != r.parameters.end()) return n->second;
  return r.parameters.count("EtaR") ? 3.0 : 0.0;
}

std::string plotCommands(const BenchResults& results, const std::string& metric,
                         const std::filesystem::path& dir, const std::string& terminal,
                         const std::string& output) {
  std::set<std::string> backends;
  for (const BenchRecord& r : results.records) backends.insert(r.backend);
  std::string series;
  int colour = 1;
  for (const std::string& backend : backends) {
    const std::string spectral = fmt::format("spectral_{}.dat", backend);
    const std::string perChannel = fmt::format("per_channel_{}.dat", backend);
    std::ofstream spectralOut(dir / spectral), perChannelOut(dir / perChannel);
    for (const BenchRecord& r : results.records) {
      if (r.backend != backend || wavelengthCount(r) == 0) continue;
      const bool isSpectral = r.parameters.count("Wavelengths") > 0;
      (isSpectral ? spectralOut : perChannelOut)
          << wavelengthCount(r) << ' ' << errorMetric(r.error, metric) << " \""
          << shortMethodName(r.method) << "\"\n";
    }
    // Backends often agree to the last digit: each later one is drawn
    // narrower, dashed and with smaller, filled marks, so it shows inside
    // the earlier one's wide line and open marks instead of hiding them.
    const bool first = colour == 1;
    series += fmt::format(
        "{}'{}' using 1:2 with linespoints lc {} lw {} dt {} pt {} ps {} title '{}: N "
        "wavelengths', "
        "'{}' using 1:2 with points lc {} pt {} ps {} title '{}: one index per channel', "
        "'{}' using 1:2:3 with labels offset 0.8,{} left font ',8' tc lt {} notitle",
        series.empty() ? "" : ", ", spectral, colour, first ? 4 : 1.5, first ? 1 : 2, first ? 6 : 7,
        first ? 2.0 : 0.8, backend, perChannel, colour, first ? 4 : 5, first ? 2.2 : 0.9, backend,
        perChannel, colour == 1 ? "0.6" : "-0.6", colour);
    ++colour;
  }
  return fmt::format(
      "set terminal {}\nset output '{}'\n"
      "set title 'Dispersion methods on the {} scene: error against the spectral reference vs "
      "wavelengths sampled ({}px)' font ',10'\n"
      "set xlabel 'wavelengths sampled (3: one index per colour channel)'\nset ylabel '{}'\n"
      "set logscale xy\nset xtics (3, 4, 8, 16, 32, 64)\nset xrange [2.5:48]\nset grid\n"
      "set key top right\nplot {}",
      terminal, output, results.scene,
      results.records.empty() ? 0 : results.records.front().errorWidth, errorMetricLabel(metric),
      series);
}

}  // namespace

bool hasWavelengthCounts(const BenchResults& results) {
  for (const BenchRecord& r : results.records)
    if (r.parameters.count("Wavelengths")) return true;
  return false;
}

std::vector<std::filesystem::path> drawWavelengthChart(const BenchResults& results,
                                                       const std::string& metric,
                                                       const std::filesystem::path& dir) {
  GnuplotBatch batch(dir);
  batch.add(plotCommands(
      results, metric, dir,
      "svg size 900,560 font 'sans,11' background '#ffffff' standalone name 'wavelengths'",
      "wavelengths.svg"));
  batch.add(plotCommands(results, metric, dir, "pngcairo size 900,560 font 'sans,10'",
                         "wavelengths.png"));
  batch.run();
  return {dir / "wavelengths.svg", dir / "wavelengths.png"};
}

}  // namespace snell::bench
