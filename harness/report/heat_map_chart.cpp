#include "report/heat_map_chart.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>

namespace snell {
namespace {

double largestAt(const Image& observed, const Image& expected, int x, int y) {
  double largest = 0;
  for (int c = 0; c < 4; ++c)
    largest = std::max(largest, double(std::abs(observed.at(x, y)[c] - expected.at(x, y)[c])));
  return largest;
}

}  // namespace

double largestDifference(const Image& observed, const Image& expected,
                         const std::vector<bool>& masked) {
  double largest = 0;
  for (int y = 0; y < observed.height; ++y)
    for (int x = 0; x < observed.width; ++x)
      if (masked.empty() || !masked[static_cast<std::size_t>(y) * observed.width + x])
        largest = std::max(largest, largestAt(observed, expected, x, y));
  return largest;
}

std::filesystem::path addHeatMap(GnuplotBatch& batch, const std::string& title,
                                 const Image& observed, const Image& expected,
                                 const std::vector<bool>& masked, double failThreshold,
                                 HeatMapSummary& summary) {
  const int w = observed.width, h = observed.height;
  // Three decades below the threshold: the bottom of the scale, where an
  // exact pixel lands too (a log scale has no 0).
  const double floor = failThreshold / 1000;
  std::vector<float> errors(static_cast<std::size_t>(w) * h);
  const std::filesystem::path points = batch.file("over", ".dat");
  std::ofstream over(points);
  summary = {};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::size_t p = static_cast<std::size_t>(y) * w + x;
      if (!masked.empty() && masked[p]) {
        errors[p] = std::numeric_limits<float>::quiet_NaN();
        continue;
      }
      const double largest = largestAt(observed, expected, x, y);
      summary.maxError = std::max(summary.maxError, largest);
      errors[p] = static_cast<float>(std::max(largest, floor));
      if (largest > failThreshold) {
        ++summary.overThreshold;
        // gnuplot's y grows upwards; row 0 of the image is the top.
        over << x << ' ' << (h - 1 - y) << '\n';
      }
    }
  const std::filesystem::path data = batch.file("errors", ".bin");
  std::ofstream(data, std::ios::binary)
      .write(reinterpret_cast<const char*>(errors.data()),
             static_cast<std::streamsize>(errors.size() * sizeof(float)));
  const std::filesystem::path png = batch.file("heat", ".png");
  const double top = std::max(failThreshold * 10, summary.maxError);
  // A few failing pixels are circled so they are found at a glance. Many
  // rings (or dots) merge into one cyan area over the very errors they
  // mark: past kRingedPixels none is drawn, and the fail threshold's mark
  // on the colour scale, always there, says which colours are over it.
  constexpr std::size_t kRingedPixels = 500;
  const bool ringed = summary.overThreshold <= kRingedPixels;
  const char* marker = summary.overThreshold <= 50 ? "pt 6 ps 1.6 lw 1.5" : "pt 6 ps 0.8 lw 1";
  std::string plot = fmt::format(
      "set terminal pngcairo size 440,360 font 'sans,9'\n"
      "set output '{}'\n"
      "set title \"{}\\n{} pixels over {:g} ({}), largest {:.3g}\"\n"
      "unset key\nset size ratio -1\nunset xtics\nunset ytics\n"
      "set xrange [-0.5:{}]\nset yrange [-0.5:{}]\n"
      "set logscale cb\nset cbrange [{:g}:{:g}]\nset format cb '%.0e'\n"
      "set cblabel 'largest channel error (log scale)'\n"
      "set cbtics add ('fail' {:g})\n"
      "set palette rgb 34,35,36\n"
      "set object 1 rect from graph 0,0 to graph 1,1 behind fc rgb '#9a9a9a' fs solid noborder\n"
      "plot '{}' binary array=({},{}) format='%float' flipy with image",
      png.filename().string(), title, summary.overThreshold, failThreshold,
      ringed ? "circled" : "too many to circle", summary.maxError, w - 0.5, h - 0.5, floor, top,
      failThreshold, data.filename().string(), w, h);
  if (summary.overThreshold > 0 && ringed)
    plot += fmt::format(", '{}' using 1:2 with points {} lc rgb '#00e5ff'",
                        points.filename().string(), marker);
  batch.add(plot);
  return png;
}

}  // namespace snell
