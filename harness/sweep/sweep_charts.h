#pragma once
// A sweep's charts, drawn by one gnuplot run: error against angle per
// backend (refract, reflect) and per Fresnel method, and maps over
// angle x eta of where each built-in, method and listing (per backend)
// breaks and why. SVG and PNG of each.
#include <filesystem>
#include <string>
#include <vector>

#include "sweep/sweep_run.h"

namespace snell::sweep {

// The charts' data, OUTDIR/sweep-data, replaced whole by every sweep.
inline constexpr const char* kChartDataFolder = "sweep-data";

// Data files go to OUTDIR/sweep-data; returns the chart files written.
std::vector<std::filesystem::path> writeSweepCharts(const SweepResult& result,
                                                    const std::filesystem::path& outDir);

// An earlier sweep's charts (sweep-*.svg, .png), their data and gnuplot's
// script and log in OUTDIR, for a sweep that draws none (--no-charts) and
// writes OUTDIR/sweep.json: they would stand beside it and contradict it.
void removeEarlierSweepCharts(const std::filesystem::path& outDir);

// What a file of this name in OUTDIR is to the charts, which write or
// remove it there: "a chart" (sweep-*.svg, .png: this sweep's are drawn
// over it, an earlier one's removed), "a chart being drawn", "gnuplot's
// script" or "gnuplot's log"; empty when it is none of these.
std::string chartFileRole(const std::string& name);

}  // namespace snell::sweep
