#pragma once
// Error against angle of incidence, drawn by gnuplot: one panel per
// backend, one line per method, the error of the pixels whose incidence
// falls in each bin (bench/angle_error.h) at the bin's centre.
#include <filesystem>
#include <string>
#include <vector>

#include "bench/bench_record.h"

namespace snell::bench {

// Writes angle.svg and angle.png (and their data files) into `dir`, which
// must exist; returns the two paths. Throws SetupError when gnuplot fails.
std::vector<std::filesystem::path> drawAngleChart(const BenchResults& results,
                                                  const std::string& metric,
                                                  const std::filesystem::path& dir);

}  // namespace snell::bench
