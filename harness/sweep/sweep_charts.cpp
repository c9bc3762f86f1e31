#include "sweep/sweep_charts.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <string_view>
#include <system_error>

#include "oracle/physics/interface_angles.h"
#include "report/gnuplot_batch.h"
#include "report/sweep_findings.h"
#include "sweep/chart_series.h"

namespace snell::sweep {
namespace {

namespace fs = std::filesystem;

struct Curve {
  std::string title;
  std::string file;  // relative to the output folder
  std::string style;
};

// Letters, digits, '.', '-' and '_' only: a gnuplot string and a file name.
std::string safe(const std::string& text) {
  std::string out;
  for (char c : text)
    out +=
        (std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '_') ? c : '-';
  return out;
}

class ChartData {
 public:
  explicit ChartData(fs::path outDir) : outDir_(std::move(outDir)) {
    fs::create_directories(outDir_ / kChartDataFolder);
  }
  // Appends (x, y) to the named curve's file.
  void add(const std::string& name, double x, double y) {
    rows_[name] += fmt::format("{:.10g} {:.10g}\n", x, y);
  }
  // Appends rows ("x y\n" each) to the named curve's file.
  void addRows(const std::string& name, const std::string& rows) { rows_[name] += rows; }
  // Writes every curve whose name starts with `prefix`; returns them, titled by the rest.
  std::vector<Curve> curves(const std::string& prefix, const std::string& style) {
    std::vector<Curve> out;
    for (const auto& [name, rows] : rows_) {
      if (name.rfind(prefix, 0) != 0) continue;
      const std::string file = std::string(kChartDataFolder) + "/" + safe(name) + ".dat";
      std::ofstream(outDir_ / file) << rows;
      out.push_back({name.substr(prefix.size()), file, style});
    }
    return out;
  }

 private:
  fs::path outDir_;
  std::map<std::string, std::string> rows_;
};

// Point types cycle (open circle, cross, filled circle, ...) and shrink
// along the series, so series that break at the same points (backends, or
// kinds of break) show as nested marks (a ring, a cross inside it, a dot
// inside that) instead of the last one drawn alone. The largest is large
// enough that the ones inside it stay apart from it.
constexpr int kPointTypes[] = {6, 2, 7, 4, 1, 8, 12, 10};
constexpr double kPointSizes[] = {1.7, 1.2, 0.6, 1.4, 0.9, 0.5, 1.1, 0.7};
constexpr std::size_t kPointStyles = std::size(kPointTypes);

// A curve whose file is empty plots its style as a gnuplot expression.
std::string plotCommands(const std::vector<Curve>& curves) {
  std::string plot = "plot ";
  for (std::size_t k = 0; k < curves.size(); ++k) {
    plot += k ? ", " : "";
    if (curves[k].file.empty())
      plot += fmt::format("{} title '{}'", curves[k].style, curves[k].title);
    else
      plot += fmt::format("'{}' using 1:2 {}{} title '{}'", curves[k].file, curves[k].style,
                          curves[k].style.find("points") != std::string::npos
                              ? fmt::format(" pt {} ps {}", kPointTypes[k % kPointStyles],
                                            kPointSizes[k % kPointStyles])
                              : "",
                          curves[k].title);
  }
  return plot + "\n";
}

// A chart of `width` x `height` pixels from a whole gnuplot body (the
// settings and the plot commands).
void addChartBody(GnuplotBatch& batch, std::vector<fs::path>& written, const fs::path& outDir,
                  const std::string& stem, const std::string& body, int width = 1100,
                  int height = 560) {
  // gnuplot's `name` is the SVG's <title> (a tooltip, and what a screen
  // reader announces): letters, digits and '_' only.
  std::string name = stem;
  std::replace_if(
      name.begin(), name.end(), [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); },
      '_');
  // Wide enough for a legend beside the plot and a title of a hundred and
  // forty characters above it (gnuplot centres the title on the plot, not
  // on the picture: at 900 pixels the longer ones were cut at both ends).
  batch.add(fmt::format(
      "set terminal svg size {},{} font 'sans,10' background '#ffffff' standalone noenhanced "
      "name '{}'\nset output '{}.svg'\n{}",
      width, height, name, stem, body));
  batch.add(fmt::format(
      "set terminal pngcairo size {},{} font 'sans,10' noenhanced\nset output '{}.png'\n{}", width,
      height, stem, body));
  written.push_back(outDir / (stem + ".svg"));
  written.push_back(outDir / (stem + ".png"));
}

void addChart(GnuplotBatch& batch, std::vector<fs::path>& written, const fs::path& outDir,
              const std::string& stem, const std::string& settings,
              const std::vector<Curve>& curves) {
  if (curves.empty()) return;
  addChartBody(batch, written, outDir, stem, settings + plotCommands(curves));
}

// The closed-form critical angle on an angle x eta map: sin(theta_c) = 1 / eta.
std::vector<Curve> withCriticalAngle(std::vector<Curve> curves) {
  curves.push_back(
      {"critical angle, eta = 1/sin(theta)", "",
       "(x > 23.5 && x <= 90 ? 1/sin(x*pi/180) : 1/0) with lines lw 1.5 lc rgb '#000000'"});
  return curves;
}

bool charted(double eta) {
  return std::abs(eta - 0.66) < 1e-9 || std::abs(eta - 1.5) < 1e-9 ||
         std::abs(eta - 1 / 1.5) < 1e-9;
}

// Inside a gnuplot single-quoted string.
std::string quotable(std::string text) {
  std::replace(text.begin(), text.end(), '\'', '"');
  return text;
}

// Class as colour (the same as the HTML report's), kind as point shape.
// Each kind of break its own colour, so that a map of eight kinds of one
// class can be read; red is kept for the implementation's (a driver's)
// breaks alone, the finding that matters most.
std::string kindColour(const std::string& cls, std::size_t kind) {
  static const char* const kOthers[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#9467bd", "#8c564b",
                                        "#e377c2", "#17becf", "#7f7f7f", "#bcbd22"};
  if (cls == "implementation") return "#d62728";
  return kOthers[kind % std::size(kOthers)];
}

// One map per listing and backend over angle x eta: where the listing
// breaks, coloured by whose fault. Breaks of a draw with no eta (0) have
// no place on the map, nor have bad inputs (zero, denormal, NaN or
// infinite vectors, drawn at one grid point): the table lists those. Back
// faces (past 90 degrees) widen the angle axis to 180.
void addListingMaps(GnuplotBatch& batch, std::vector<fs::path>& written, const fs::path& outDir,
                    const ListingSweepResult& listings, const std::string& mapAxes) {
  using Curves = std::map<std::pair<std::string, std::string>, std::string>;  // (class, kind)
  std::map<std::pair<std::string, std::string>, Curves> maps;                 // (listing, backend)
  std::map<std::pair<std::string, std::string>, bool> backFaces;
  for (const ListingBreak& b : listings.breaks) {
    if (!(b.eta > 0) || !std::isfinite(b.angleDegrees)) continue;
    if (b.input != "grid" && b.input != "back-face") continue;
    if (b.angleDegrees > 90) backFaces[{b.listing, b.backend}] = true;
    const std::string kind = b.kind + (b.frame == "unit" ? "" : ", " + b.frame);
    maps[{b.listing, b.backend}][{breakClassName(b.cls), kind}] +=
        fmt::format("{:.10g} {:.10g}\n", b.angleDegrees, b.eta);
  }
  for (const auto& [key, curves] : maps) {
    const std::string stem = listingMapStem(key.first, key.second);
    std::vector<Curve> plotted;
    int n = 0;
    for (const auto& [classKind, rows] : curves) {
      const std::string file = fmt::format("{}/{}-{}.dat", kChartDataFolder, stem, n++);
      std::ofstream(outDir / file) << rows;
      plotted.push_back(
          {fmt::format("{} ({})", classKind.second, classKind.first), file,
           fmt::format("with points lc rgb '{}'", kindColour(classKind.first, plotted.size()))});
    }
    const std::string angles =
        backFaces[key] ? "set xrange [0:180]\nset xlabel 'incidence angle (degrees; past 90: "
                         "back faces)'\nset arrow from 90, graph 0 to 90, graph 1 nohead dt 3\n"
                       : "";
    addChart(batch, written, outDir, stem,
             mapAxes + angles +
                 fmt::format("set title '{} on {}: where it breaks (bad inputs: in the table)'\n"
                             "set key outside right top Left reverse font ',10' title 'kind "
                             "(class)'\n",
                             quotable(key.first), quotable(key.second)),
             withCriticalAngle(plotted));
  }
}

// Each method's line, the same in every panel. Drawn in the methods'
// order, a later line is narrower or dashed, so one that lies on an
// earlier one (schlick_dense_side is schlick where n1 < n2) stays visible.
std::string methodLine(const std::string& method) {
  if (method == "constant") return "with lines lw 4 lc rgb '#9467bd'";
  if (method == "exact") return "with lines lw 3 lc rgb '#2ca02c'";
  if (method == "schlick") return "with lines lw 2 lc rgb '#1f77b4'";
  return "with lines lw 2 dt 2 lc rgb '#ff7f0e'";
}

// The Fresnel methods' error against angle: one column per side of the
// interface (the two are different curves: on one line the light going
// into the dense medium hid the one coming out of it), the whole range
// above and the band around the bound below (on the whole range, down to
// -1, the bound's +-0.02 is a few pixels). Exact Fresnel in double is the
// reference itself: drawn only where it is not 0 throughout.
void addMethodErrorChart(GnuplotBatch& batch, std::vector<fs::path>& written,
                         const fs::path& outDir, const std::vector<MethodSample>& samples) {
  std::map<double, std::map<std::string, std::string>> bySide;  // eta -> method -> rows
  bool exactIsZero = true;
  for (const MethodSample& s : samples) {
    if (!charted(s.eta) || std::abs(s.eta - 0.66) < 1e-9) continue;
    if (s.method == "exact" && s.error() != 0) exactIsZero = false;
    bySide[s.eta][s.method] += fmt::format("{:.10g} {:.10g}\n", s.angleDegrees, s.error());
  }
  if (bySide.empty()) return;
  // One column per side: its title, the dotted critical angle where there
  // is one (gnuplot's arrows carry over from panel to panel), its plot.
  struct Column {
    std::string title, critical, plot;
  };
  std::vector<Column> columns;
  for (const auto& [eta, methods] : bySide) {
    std::vector<std::string> names, rows;
    for (const auto& [method, data] : methods) {
      if (method == "exact" && exactIsZero) continue;
      names.push_back(method);
      rows.push_back(data);
    }
    const std::vector<std::optional<std::size_t>> same = sameAsEarlier(rows);
    std::string plot = "plot ";
    for (std::size_t k = 0; k < names.size(); ++k) {
      const std::string file =
          fmt::format("{}/error-{}-eta-{:.4g}.dat", kChartDataFolder, safe(names[k]), eta);
      std::ofstream(outDir / file) << rows[k];
      const std::string title =
          same[k] ? fmt::format("{} (the same as {} here)", names[k], names[*same[k]]) : names[k];
      plot += fmt::format("{}'{}' using 1:2 {} title '{}'", k ? ", " : "", file,
                          methodLine(names[k]), title);
    }
    Column column{fmt::format("n1 < n2 (eta {:.4g}): into the denser medium", eta),
                  "unset arrow 3\n", plot + "\n"};
    if (eta > 1) {
      const double critical = physics::criticalAngleDegrees(eta, 1.0);
      column.title = fmt::format(
          "n1 > n2 (eta {:.4g}): total internal reflection past {:.4g} (dotted)", eta, critical);
      column.critical =
          fmt::format("set arrow 3 from {0},graph 0 to {0},graph 1 nohead dt 3\n", critical);
    }
    columns.push_back(column);
  }
  std::string body = fmt::format(
      "set xlabel 'incidence angle (degrees)'\nset xrange [0:90]\nset grid\nset ylabel "
      "'error'\nset arrow 1 from 0,{0} to 90,{0} nohead dt 2\n"
      "set arrow 2 from 0,-{0} to 90,-{0} nohead dt 2\n"
      "set multiplot layout 2,{1} title 'Fresnel methods: reflectance minus exact Fresnel (the "
      "bound {0}: dashed black){2}'\n",
      kMethodErrorBound, columns.size(),
      exactIsZero ? "; exact Fresnel in double is the reference, 0 throughout, not drawn" : "");
  for (const Column& column : columns)
    body += fmt::format("set title '{}'\nset yrange [*:*]\nset key bottom left opaque box\n{}{}",
                        column.title, column.critical, column.plot);
  for (const Column& column : columns)
    body += fmt::format(
        "set title 'the same, near the bound ({0:.4g} to {1:.4g})'\nset yrange "
        "[{0:.4g}:{1:.4g}]\nunset key\n{2}{3}",
        -5 * kMethodErrorBound, 5 * kMethodErrorBound, column.critical, column.plot);
  addChartBody(batch, written, outDir, "sweep-method-error", body + "unset multiplot\n", 1100, 820);
}

// The sweep's charts are named sweep-*.svg and .png.
bool isChartName(const std::string& name) {
  const fs::path extension = fs::path(name).extension();
  return name.starts_with("sweep-") && (extension == ".svg" || extension == ".png");
}

// The charts of an earlier sweep in the same folder that this one did not
// draw (another backend's map, a listing no longer swept) would stand
// beside its results and contradict them: those it did not draw now are
// removed.
void removeEarlierCharts(const fs::path& outDir, const std::vector<fs::path>& written) {
  std::set<fs::path> drawn;
  for (const fs::path& path : written) drawn.insert(path.filename());
  std::error_code error;
  std::vector<fs::path> stale;
  for (const fs::directory_entry& entry : fs::directory_iterator(outDir, error)) {
    const fs::path& path = entry.path();
    if (isChartName(path.filename().string()) && entry.is_regular_file(error) &&
        !drawn.count(path.filename()))
      stale.push_back(path);
  }
  for (const fs::path& path : stale) fs::remove(path, error);
}

// sweep-data/ is the charts' own, written whole each time: an earlier
// sweep's data (another backend's) goes with it.
void removeEarlierChartData(const fs::path& outDir) {
  std::error_code ignored;
  fs::remove_all(outDir / kChartDataFolder, ignored);
}

}  // namespace

void removeEarlierSweepCharts(const fs::path& outDir) {
  removeEarlierChartData(outDir);
  removeEarlierCharts(outDir, {});
  std::error_code ignored;
  fs::remove(outDir / GnuplotBatch::kScript, ignored);
  fs::remove(outDir / GnuplotBatch::kLog, ignored);
}

std::string chartFileRole(const std::string& name) {
  if (isChartName(name)) return "a chart";
  const std::string_view drawing = GnuplotBatch::kDrawing;
  if (name.ends_with(drawing) && isChartName(name.substr(0, name.size() - drawing.size())))
    return "a chart being drawn";
  if (name == GnuplotBatch::kScript) return "gnuplot's script";
  if (name == GnuplotBatch::kLog) return "gnuplot's log";
  return "";
}

std::vector<fs::path> writeSweepCharts(const SweepResult& result, const fs::path& outDir) {
  removeEarlierChartData(outDir);
  ChartData data(outDir);
  double reflectWorst = 0;
  for (const BackendSweep& sweep : result.sweeps) {
    if (sweep.backend == "oracle") continue;  // its slack is the reference itself
    for (std::size_t k = 0; k < result.points.size(); ++k) {
      const SweepPoint& p = result.points[k];
      const Observation& o = sweep.points[k];
      if (p.input != "grid" || !o.answered || !std::isfinite(o.slack)) continue;
      if (p.call.fn == "refract" && charted(p.eta))
        data.add(fmt::format("slack/refract/{} eta {:.4g}", sweep.backend, p.eta), p.angleDegrees,
                 o.slack);
      if (p.call.fn == "reflect") {
        data.add("slack/reflect/" + sweep.backend, p.angleDegrees, o.slack);
        reflectWorst = std::max(reflectWorst, o.slack);
      }
    }
  }
  std::vector<MapMark> refractMarks, methodMarks;
  for (const Break& b : result.breaks) {
    const SweepPoint& p = result.points[b.point];
    if (p.input != "grid" || p.call.fn != "refract") continue;
    refractMarks.push_back(
        {b.backend, fmt::format("{} ({})", b.kind, breakClassName(b.cls)), p.angleDegrees, p.eta});
  }
  for (const auto& [title, rows] : mergedMarks(refractMarks))
    data.addRows("map/refract/" + title, rows);
  for (const Break& b : result.methodBreaks) {
    const MethodSample& s = result.methodSamples[b.point];
    methodMarks.push_back({s.method, b.kind, s.angleDegrees, s.eta});
  }
  for (const auto& [title, rows] : mergedMarks(methodMarks))
    data.addRows("map/method/" + title, rows);

  GnuplotBatch batch(outDir);
  std::vector<fs::path> written;
  const std::string angleAxis =
      "set xlabel 'incidence angle (degrees)'\nset xrange [0:90]\nset grid\n"
      "set key outside right\n";
  // Without the built-ins (--no-builtins) their charts would be empty
  // plots that read as "no breaks": not drawn.
  const bool builtins = !result.points.empty();
  if (builtins)
    addChart(batch, written, outDir, "sweep-refract-slack",
             angleAxis +
                 "set title 'refract(): slack (error / allowed error) against angle, eta 0.66, "
                 "1/1.5 and 1.5 where swept (total internal reflection, the zero vector, at 0)'\n"
                 "set ylabel 'slack (1 = edge of the spec)'\nset yrange [0:*]\n",
             data.curves("slack/refract/", "with points"));
  if (builtins)
    addChart(
        batch, written, outDir, "sweep-reflect-slack",
        angleAxis +
            fmt::format("set title 'reflect(): slack (error / allowed error) against angle{}'\n"
                        "set ylabel 'slack (1 = edge of the spec)'\nset yrange [{}]\n",
                        // All 0 is a result: said, and the points kept off the axis line.
                        reflectWorst > 0 ? "" : " (every result exact: slack 0 throughout)",
                        reflectWorst > 0 ? "0:*" : "-0.05:1"),
        data.curves("slack/reflect/", "with points"));
  addMethodErrorChart(batch, written, outDir, result.methodSamples);
  const std::string mapAxes =
      "set xlabel 'incidence angle (degrees)'\nset ylabel 'eta (n1/n2)'\n"
      "set xrange [0:90]\nset yrange [0.25:2.55]\nset grid\n"
      "set key outside right\nset samples 1000\n";
  if (builtins)
    addChart(batch, written, outDir, "sweep-map-refract",
             mapAxes + "set title 'refract(): where each backend breaks, and why'\n",
             withCriticalAngle(data.curves("map/refract/", "with points")));
  addChart(batch, written, outDir, "sweep-map-methods",
           mapAxes + fmt::format("set title 'Fresnel methods: breaks against exact Fresnel "
                                 "(error bound {}, physical range)'\n",
                                 kMethodErrorBound),
           withCriticalAngle(data.curves("map/method/", "with points")));
  if (result.listingsSwept) addListingMaps(batch, written, outDir, result.listings, mapAxes);
  batch.run();
  removeEarlierCharts(outDir, written);
  return written;
}

}  // namespace snell::sweep
