#pragma once
// The terminal table of a bench run: per backend, each method's time per
// frame with its spread and its errors, the Pareto front marked; then the
// time per frame by sphere tessellation.
#include <string>

#include "bench/bench_record.h"

namespace snell::bench {

std::string benchTable(const BenchResults& results, const std::string& metric);

// Per backend, each method's median ms per frame at each tessellation;
// empty when the run timed none.
std::string tessellationTable(const BenchResults& results);

}  // namespace snell::bench
