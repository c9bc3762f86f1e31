#pragma once
// The speed/accuracy chart of a bench run, drawn by gnuplot: error against
// time per frame, one colour per backend, each method a labelled point and
// each backend's Pareto front a line through its points. Labels are placed
// apart so that methods at nearly the same place stay readable.
#include <filesystem>
#include <string>
#include <vector>

#include "bench/bench_record.h"

namespace snell::bench {

// Writes pareto.svg and pareto.png (and their data files) into `dir`, which
// must exist; returns the two paths. Throws SetupError when gnuplot fails.
std::vector<std::filesystem::path> drawParetoChart(const BenchResults& results,
                                                   const std::string& metric,
                                                   const std::filesystem::path& dir);

// A point's place on the Pareto chart in character cells from the plot
// area's lower left, for label placement (bench/label_placement.h): time
// on a linear axis, error on a logarithmic one, between the axis ranges.
double labelColumn(double x, double low, double high);
double labelLine(double y, double low, double high);

// The axis label of an error metric ("mean CIEDE2000").
const char* errorMetricLabel(const std::string& metric);

// The ladder a method belongs to: the middle part of "methods/fresnel/x".
std::string ladderName(const std::string& id);

// The short name of a method: the last part of its id ("6-exact-fragment").
std::string shortMethodName(const std::string& id);

}  // namespace snell::bench
