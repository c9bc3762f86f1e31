#include "bench/vertex_chart.h"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <set>

#include "bench/bench_chart.h"
#include "report/gnuplot_batch.h"

namespace snell::bench {
namespace {

std::string plotCommands(const BenchResults& results, const std::filesystem::path& dir,
                         const std::string& terminal, const std::string& output) {
  std::set<std::string> backends;
  for (const BenchRecord& r : results.records) backends.insert(r.backend);
  const int width = results.records.empty() || results.records.front().byTessellation.empty()
                        ? 0
                        : results.records.front().byTessellation.front().timing.width;
  std::string out = fmt::format(
      "set terminal {}\nset output '{}'\n"
      "set multiplot layout 1,{} title '{} methods on the {} scene: time per frame against "
      "vertex count ({}px; the sphere at several tessellations)' font ',10'\n",
      terminal, output, backends.size(),
      results.records.empty() ? std::string("no") : ladderName(results.records.front().method),
      results.scene, width);
  // One time axis for every panel: side by side, panels on scales of their
  // own invite reading one backend's bars against the other's.
  double top = 0;
  for (const BenchRecord& r : results.records)
    for (const TessellationTiming& t : r.byTessellation)
      top = std::max({top, t.timing.p90Ms, t.timing.medianMs});
  out += fmt::format("set yrange [0:{}]\n", top > 0 ? top * 1.05 : 1.0);
  for (const std::string& backend : backends) {
    std::string series;
    int colour = 1;
    for (const BenchRecord& r : results.records) {
      if (r.backend != backend || r.byTessellation.empty()) continue;
      const std::string data = fmt::format("vertices_{}_{}.dat", backend, colour);
      std::ofstream file(dir / data);
      for (const TessellationTiming& t : r.byTessellation)
        file << t.vertices << ' ' << t.timing.medianMs << ' ' << t.timing.p10Ms << ' '
             << t.timing.p90Ms << '\n';
      series +=
          fmt::format("{0}'{1}' using 1:2:3:4 with yerrorlines lc {2} lw 2 pt 7 ps 0.8 title '{3}'",
                      series.empty() ? "" : ", ", data, colour, shortMethodName(r.method));
      ++colour;
    }
    out += fmt::format(
        "set title '{}'\nset xlabel 'vertices (log scale)'\n"
        "set ylabel 'ms per frame (median, bars: 10th-90th percentile)'\nset logscale x\n"
        "set grid\nset key top left font ',8'\nplot {}\n",
        backend, series);
  }
  return out + "unset multiplot";
}

}  // namespace

bool hasTessellations(const BenchResults& results) {
  for (const BenchRecord& r : results.records)
    if (r.byTessellation.size() > 1) return true;
  return false;
}

std::vector<std::filesystem::path> drawVertexChart(const BenchResults& results,
                                                   const std::filesystem::path& dir) {
  GnuplotBatch batch(dir);
  batch.add(plotCommands(
      results, dir,
      "svg size 1200,520 font 'sans,11' background '#ffffff' standalone name 'time_by_vertices'",
      "vertices.svg"));
  batch.add(plotCommands(results, dir, "pngcairo size 1200,520 font 'sans,10'", "vertices.png"));
  batch.run();
  return {dir / "vertices.svg", dir / "vertices.png"};
}

}  // namespace snell::bench
