#pragma once
// What physics says about the order of a ladder's errors, checked on a
// bench run: sampling more wavelengths of the same glass never moves a
// method away from the spectral reference by more than the measurement's
// noise.
#include <string>
#include <vector>

#include "bench/bench_record.h"

namespace snell::bench {

// The noise of an error measurement, per metric: what fp32 shading and
// 8-bit bilinear weights move a picture by, far below what a display shows.
// rms and max in linear RGB (1/255 is one 8-bit step); CIEDE2000 in its own
// units (about 1 is a just-noticeable difference).
double errorNoise(const std::string& metric);

// One line per pair of spectral methods (manifest constant `Wavelengths`)
// on one backend where the one with more wavelengths is farther from the
// reference than one with fewer, by more than `noise`; empty when none is.
std::vector<std::string> wavelengthOrderViolations(const BenchResults& results,
                                                   const std::string& metric, double noise);

}  // namespace snell::bench
