#pragma once
// How the time per frame grows with the vertex count: one panel per
// backend, one line per method, the sphere at each tessellation timed,
// drawn by gnuplot.
#include <filesystem>
#include <vector>

#include "bench/bench_record.h"

namespace snell::bench {

// True when the run timed more than one tessellation.
bool hasTessellations(const BenchResults& results);

// Writes vertices.svg and vertices.png (and their data files) into `dir`;
// returns the two paths. Throws SetupError when gnuplot fails.
std::vector<std::filesystem::path> drawVertexChart(const BenchResults& results,
                                                   const std::filesystem::path& dir);

}  // namespace snell::bench
