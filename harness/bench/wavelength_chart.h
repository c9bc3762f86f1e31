#pragma once
// The dispersion ladder's second chart, drawn by gnuplot: error against the
// number of wavelengths a method samples, one line per backend through the
// spectral methods (Wavelengths in their manifests) and the per-channel
// methods (EtaR, EtaG, EtaB) as labelled points at 3.
#include <filesystem>
#include <string>
#include <vector>

#include "bench/bench_record.h"

namespace snell::bench {

// Whether the results hold a method with a wavelength count.
bool hasWavelengthCounts(const BenchResults& results);

// Writes wavelengths.svg and wavelengths.png (and their data files) into
// `dir`, which must exist; returns the two paths. Throws SetupError when
// gnuplot fails.
std::vector<std::filesystem::path> drawWavelengthChart(const BenchResults& results,
                                                       const std::string& metric,
                                                       const std::filesystem::path& dir);

}  // namespace snell::bench
