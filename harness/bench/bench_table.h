#pragma once
// The terminal table of a bench run: per backend, each method's time per
// frame with its spread and its errors, the Pareto front marked.
#include <string>

#include "bench/bench_record.h"

namespace snell::bench {

std::string benchTable(const BenchResults& results, const std::string& metric);

}  // namespace snell::bench
