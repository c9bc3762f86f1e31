#include "bench/bench_chart.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <set>

#include "bench/label_placement.h"
#include "bench/pareto_front.h"
#include "report/gnuplot_batch.h"

namespace snell::bench {
namespace {

// The plot area of the 900 x 560 terminals below, in character cells of
// their fonts (gnuplot's GPVAL_TERM_* for the PNG and SVG terminals, the
// smaller of the two), and the labels' font (8 point) against theirs.
constexpr double kPlotColumns = 100.0;
constexpr double kPlotLines = 27.5;
constexpr double kLabelScale = 0.8;

// Explicit axis ranges, so that label places can be computed in the
// chart's own space: time linear, error logarithmic.
struct ChartRanges {
  double xLow = 0, xHigh = 1, yLow = 1e-3, yHigh = 1;
};

ChartRanges chartRanges(const std::vector<std::pair<double, double>>& points) {
  ChartRanges r;
  if (points.empty()) return r;
  double xMin = points.front().first, xMax = xMin;
  double yMin = points.front().second, yMax = yMin;
  for (const auto& [x, y] : points) {
    xMin = std::min(xMin, x);
    xMax = std::max(xMax, x);
    yMin = std::min(yMin, y);
    yMax = std::max(yMax, y);
  }
  const double span = xMax > xMin ? xMax - xMin : std::max(xMax, 1e-3) * 0.2;
  // Room on the right for the labels, as much as the longest needs.
  r.xLow = xMin - 0.05 * span;
  r.xHigh = xMax + 0.35 * span;
  r.yLow = yMin / 1.8;
  r.yHigh = yMax * 1.8;
  return r;
}

std::string plotCommands(const BenchResults& results, const std::string& metric,
                         const std::filesystem::path& dir, const std::string& terminal,
                         const std::string& output) {
  std::set<std::string> backends;
  for (const BenchRecord& r : results.records) backends.insert(r.backend);
  // Errors of 0 (a method equal to the reference) cannot sit on a log axis:
  // they are drawn at the axis' floor.
  auto shownError = [&](const BenchRecord& r) {
    return std::max(errorMetric(r.error, metric), 1e-6);
  };
  // The 10th-90th percentile spread of each time, drawn as a bar: two
  // methods whose bars overlap were not told apart by this run.
  const auto spread = [](const BenchRecord& r) {
    const FrameTiming* t = r.timings.empty() ? nullptr : &r.timings.back();
    const bool measured = t && t->p90Ms >= t->p10Ms && t->p10Ms > 0;
    return measured ? std::pair{t->p10Ms, t->p90Ms} : std::pair{r.msPerFrame(), r.msPerFrame()};
  };
  std::vector<std::pair<double, double>> all;
  for (const BenchRecord& r : results.records) {
    all.push_back({spread(r).first, shownError(r)});
    all.push_back({spread(r).second, shownError(r)});
  }
  const ChartRanges ranges = chartRanges(all);

  std::string series;
  std::vector<LabelledPoint> labelled;
  std::vector<int> labelColours;
  std::vector<std::pair<double, double>> labelAt;  // data coordinates, beside `labelled`
  int colour = 1;
  for (const std::string& backend : backends) {
    const std::string points = fmt::format("points_{}.dat", backend);
    const std::string front = fmt::format("front_{}.dat", backend);
    std::vector<CostError> costs;
    {
      std::ofstream out(dir / points);
      for (const BenchRecord& r : results.records) {
        if (r.backend != backend) continue;
        const double error = shownError(r);
        out << r.msPerFrame() << ' ' << error << " \"" << shortMethodName(r.method) << "\" "
            << spread(r).first << ' ' << spread(r).second << '\n';
        costs.push_back({r.msPerFrame(), error});
        labelled.push_back({labelColumn(r.msPerFrame(), ranges.xLow, ranges.xHigh),
                            labelLine(error, ranges.yLow, ranges.yHigh),
                            shortMethodName(r.method)});
        labelColours.push_back(colour);
        labelAt.push_back({r.msPerFrame(), error});
      }
    }
    {
      std::ofstream out(dir / front);
      for (std::size_t i : paretoFront(costs))
        out << costs[i].cost << ' ' << costs[i].error << '\n';
    }
    series += fmt::format(
        "{}'{}' using 1:2 with linespoints lc {} lw 2 pt 7 ps 1.4 title '{} Pareto front', "
        "'{}' using 1:2:4:5 with xerrorbars lc {} pt 6 ps 1.4 notitle",
        series.empty() ? "" : ", ", front, colour, backend, points, colour);
    ++colour;
  }
  std::string labels;
  const std::vector<LabelOffset> offsets = placeLabels(labelled, kLabelScale);
  for (std::size_t i = 0; i < labelled.size(); ++i) {
    labels += fmt::format(
        "set label {} '{}' at first {}, first {} offset character {:.2f},{:.2f} left font ',8' "
        "tc lt {} front\n",
        i + 1, labelled[i].text, labelAt[i].first, labelAt[i].second, offsets[i].dx, offsets[i].dy,
        labelColours[i]);
    // A label moved off its nearest place gets a faint leader to its point.
    if (std::abs(offsets[i].dy) > 1.0 || offsets[i].dx < 0) {
      const LabelBox box = labelBox(labelled[i], offsets[i], kLabelScale);
      const double end = offsets[i].dx < 0 ? box.right - labelled[i].x : offsets[i].dx;
      labels += fmt::format(
          "set arrow {} from first {}, first {} rto character {:.2f},{:.2f} nohead lc {} lw 0.6 "
          "dt 3 back\n",
          i + 1, labelAt[i].first, labelAt[i].second, end, offsets[i].dy, labelColours[i]);
    }
  }
  return fmt::format(
      "set terminal {}\nset output '{}'\n"
      "set title '{} methods on the {} scene: error against the physics reference vs time "
      "per frame ({}px)' font ',10'\n"
      "set xlabel 'ms per frame (median of warm repeats; bars: 10th to 90th percentile)'\n"
      "set ylabel '{}'\n"
      "set logscale y\nset grid\nset key top right\nset xrange [{}:{}]\nset yrange [{}:{}]\n"
      "{}plot {}",
      terminal, output,
      results.records.empty() ? std::string("no") : ladderName(results.records.front().method),
      results.scene, results.records.empty() ? 0 : results.records.front().errorWidth,
      errorMetricLabel(metric), ranges.xLow, ranges.xHigh, ranges.yLow, ranges.yHigh, labels,
      series);
}

}  // namespace

double labelColumn(double x, double low, double high) {
  return high > low ? (x - low) / (high - low) * kPlotColumns : 0.0;
}

double labelLine(double y, double low, double high) {
  return high > low && y > 0 && low > 0
             ? (std::log(y) - std::log(low)) / (std::log(high) - std::log(low)) * kPlotLines
             : 0.0;
}

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
  batch.add(
      plotCommands(results, metric, dir,
                   "svg size 900,560 font 'sans,11' background '#ffffff' standalone name 'pareto'",
                   "pareto.svg"));
  batch.add(
      plotCommands(results, metric, dir, "pngcairo size 900,560 font 'sans,10'", "pareto.png"));
  batch.run();
  return {dir / "pareto.svg", dir / "pareto.png"};
}

}  // namespace snell::bench
