#include "bench/angle_chart.h"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <set>

#include "bench/bench_chart.h"
#include "report/gnuplot_batch.h"

namespace snell::bench {
namespace {

std::string plotCommands(const BenchResults& results, const std::string& metric,
                         const std::filesystem::path& dir, const std::string& terminal,
                         const std::string& output) {
  std::set<std::string> backends;
  for (const BenchRecord& r : results.records) backends.insert(r.backend);
  std::string out = fmt::format(
      "set terminal {}\nset output '{}'\n"
      "set multiplot layout 1,{} title '{} methods on the {} scene: error against the physics "
      "reference by angle of incidence ({}px)' font ',10'\n",
      terminal, output, backends.size(),
      results.records.empty() ? std::string("no") : ladderName(results.records.front().method),
      results.scene, results.records.empty() ? 0 : results.records.front().errorWidth);
  for (const std::string& backend : backends) {
    std::string series;
    int colour = 1;
    for (const BenchRecord& r : results.records) {
      if (r.backend != backend || r.errorByAngle.empty()) continue;
      const std::string data = fmt::format("angle_{}_{}.dat", backend, colour);
      std::ofstream file(dir / data);
      for (const AngleBin& bin : r.errorByAngle)
        if (bin.error.compared > 0)
          file << 0.5 * (bin.fromDeg + bin.toDeg) << ' ' << errorMetric(bin.error, metric) << '\n';
      // Methods that converge (more wavelengths past the point where they
      // stop mattering) give the same curve: each later one is drawn
      // narrower and with smaller marks, on top, so the earlier one shows
      // around it instead of being hidden.
      const int later = std::min(colour - 1, 5);
      series +=
          fmt::format("{}'{}' using 1:2 with linespoints lc {} lw {:.1f} pt 7 ps {:.2f} title '{}'",
                      series.empty() ? "" : ", ", data, colour, 5.0 - 0.8 * later,
                      2.0 - 0.3 * later, shortMethodName(r.method));
      ++colour;
    }
    out += fmt::format(
        "set title '{}'\nset xlabel 'angle of incidence (degrees; bin centres)'\n"
        "set ylabel '{}'\nset logscale y\nset grid\nset xrange [0:90]\nset xtics 10\n"
        "set key bottom right font ',8'\nplot {}\n",
        backend, errorMetricLabel(metric), series);
  }
  return out + "unset multiplot";
}

}  // namespace

std::vector<std::filesystem::path> drawAngleChart(const BenchResults& results,
                                                  const std::string& metric,
                                                  const std::filesystem::path& dir) {
  GnuplotBatch batch(dir);
  batch.add(plotCommands(
      results, metric, dir,
      "svg size 1200,520 font 'sans,11' background '#ffffff' standalone name 'error_by_angle'",
      "angle.svg"));
  batch.add(
      plotCommands(results, metric, dir, "pngcairo size 1200,520 font 'sans,10'", "angle.png"));
  batch.run();
  return {dir / "angle.svg", dir / "angle.png"};
}

}  // namespace snell::bench
