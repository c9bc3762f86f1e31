#pragma once
// What a sweep found, for machines (JSON), for people (a table on the
// terminal); the charts are in sweep_charts.h.
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "sweep/sweep_run.h"

namespace snell::sweep {

// Every break (builtins and methods) with its parameters, value and class,
// the critical angles, a summary and the wall time.
void writeSweepJson(const SweepResult& result, const std::filesystem::path& path);

// Breaks grouped by function or method, backend, input, kind and class,
// with their angle and eta ranges; then the critical angles.
void printSweepTable(const SweepResult& result, std::FILE* out);

}  // namespace snell::sweep
