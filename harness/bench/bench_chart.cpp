#include "bench/bench_chart.h"

#include <fmt/format.h>

#include <cctype>
#include <fstream>
#include <set>

#include "bench/pareto_front.h"
#include "report/gnuplot_batch.h"

namespace snell::bench {
namespace {

std::string plotCommands(const BenchResults& results, const std::string& metric,
                         const std::filesystem::path& dir, const std::string& terminal,
                         const std::string& output) {
  std::set<std::string> backends;
  for (const BenchRecord& r : results.records) backends.insert(r.backend);
  std::string series;
  int colour = 1;
  for (const std::string& backend : backends) {
    const std::string points = fmt::format("points_{}.dat", backend);
    const std::string front = fmt::format("front_{}.dat", backend);
    std::vector<CostError> costs;
    {
      std::ofstream out(dir / points);
      for (const BenchRecord& r : results.records) {
        if (r.backend != backend) continue;
        const double error = errorMetric(r.error, metric);
        out << r.msPerFrame() << ' ' << error << " \"" << shortMethodName(r.method) << "\"\n";
        costs.push_back({r.msPerFrame(), error});
      }
    }
    {
      std::ofstream out(dir / front);
      for (std::size_t i : paretoFront(costs))
        out << costs[i].cost << ' ' << costs[i].error << '\n';
    }
    series += fmt::format(
        "{}'{}' using 1:2 with linespoints lc {} lw 2 pt 7 ps 1.4 title '{} Pareto front', "
        "'{}' using 1:2 with points lc {} pt 6 ps 1.4 notitle, "
        "'{}' using 1:2:3 with labels offset 0.8,0.6 left font ',8' tc lt {} notitle",
        series.empty() ? "" : ", ", front, colour, backend, points, colour, points, colour);
    ++colour;
  }
  return fmt::format(
      "set terminal {}\nset output '{}'\n"
      "set title '{} methods on the {} scene: error against the physics reference vs time "
      "per frame ({}px)' font ',10'\n"
      "set xlabel 'ms per frame (median of warm repeats)'\nset ylabel '{}'\n"
      "set logscale y\nset grid\nset key top right\nset offsets graph 0.05, graph 0.3, 0, 0\n"
      "plot {}",
      terminal, output,
      results.records.empty() ? std::string("no") : ladderName(results.records.front().method),
      results.scene, results.records.empty() ? 0 : results.records.front().errorWidth,
      errorMetricLabel(metric), series);
}

}  // namespace

const char* errorMetricLabel(const std::string& metric) {
  if (metric == "rms") return "RMS error, linear RGB";
  if (metric == "max") return "largest channel error, linear RGB";
  if (metric == "de_p95") return "95th percentile CIEDE2000";
  return "mean CIEDE2000";
}

std::string ladderName(const std::string& id) {
  const std::size_t last = id.rfind('/');
  if (last == std::string::npos || last == 0) return id;
  const std::size_t before = id.rfind('/', last - 1);
  const std::string name = id.substr(before == std::string::npos ? 0 : before + 1,
                                     last - (before == std::string::npos ? 0 : before + 1));
  return name.empty() ? id
                      : std::string(1, static_cast<char>(std::toupper(name[0]))) + name.substr(1);
}

std::string shortMethodName(const std::string& id) {
  const std::size_t slash = id.rfind('/');
  return slash == std::string::npos ? id : id.substr(slash + 1);
}

std::vector<std::filesystem::path> drawParetoChart(const BenchResults& results,
                                                   const std::string& metric,
                                                   const std::filesystem::path& dir) {
  GnuplotBatch batch(dir);
  batch.add(plotCommands(results, metric, dir,
                         "svg size 900,560 font 'sans,11' background '#ffffff' standalone",
                         "pareto.svg"));
  batch.add(
      plotCommands(results, metric, dir, "pngcairo size 900,560 font 'sans,10'", "pareto.png"));
  batch.run();
  return {dir / "pareto.svg", dir / "pareto.png"};
}

}  // namespace snell::bench
