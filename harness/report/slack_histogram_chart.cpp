#include "report/slack_histogram_chart.h"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>

namespace snell {

std::vector<std::string> slackBinLabels() {
  return {"0", "≤1/64", "≤1/16", "≤1/4", "≤1/2", "≤1", "≤2", ">2"};
}

std::filesystem::path addSlackHistogram(GnuplotBatch& batch,
                                        const std::vector<VaryingCheck>& varyings) {
  const std::filesystem::path data = batch.file("slack", ".dat");
  const std::vector<std::string> labels = slackBinLabels();
  {
    std::ofstream out(data);
    for (std::size_t bin = 0; bin < labels.size(); ++bin) {
      out << '"' << labels[bin] << '"';
      for (const VaryingCheck& v : varyings) out << ' ' << v.slackHistogram[bin];
      out << '\n';
    }
  }
  // gnuplot's autoscale clips the tallest clustered bar: the top is set.
  std::size_t tallest = 1;
  for (const VaryingCheck& v : varyings)
    for (std::size_t n : v.slackHistogram) tallest = std::max(tallest, n);
  std::string series;
  for (std::size_t k = 0; k < varyings.size(); ++k)
    series += fmt::format("{}'{}' using {}{} title '{}'", k ? ", " : "", data.filename().string(),
                          k + 2, k ? "" : ":xtic(1)", varyings[k].name);
  const std::filesystem::path svg = batch.file("slack", ".svg");
  batch.add(fmt::format(
      "set terminal svg size 560,240 font 'sans,10' background '#ffffff' name 'slack_histogram'\n"
      "set output '{}'\n"
      "set style data histogram\nset style histogram clustered gap 1\n"
      "set style fill solid 0.8 border -1\nset boxwidth 0.9\n"
      "set logscale y\nset yrange [0.7:{}]\nset ylabel 'components'\n"
      "set xlabel 'slack (observed error / allowed error; over 1 is outside the spec)'\n"
      // Outside the plot: inside, the key sat over the out-of-spec bins.
      "set key outside right top font 'sans,9'\n"
      "set object 1 rect from 5.5, graph 0 to 7.5, graph 1 behind fc rgb '#fde0dc' fs solid "
      "noborder\n"
      "plot {}",
      svg.filename().string(), tallest * 3, series));
  return svg;
}

}  // namespace snell
