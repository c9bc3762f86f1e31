#pragma once
// The speed/accuracy chart of a bench run, drawn by gnuplot: error against
// time per frame, one colour per backend, each method a labelled point and
// each backend's Pareto front a line through its points.
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

// The axis label of an error metric ("mean CIEDE2000").
const char* errorMetricLabel(const std::string& metric);

// The ladder a method belongs to: the middle part of "methods/fresnel/x".
std::string ladderName(const std::string& id);

// The short name of a method: the last part of its id ("6-exact-fragment").
std::string shortMethodName(const std::string& id);

}  // namespace snell::bench
