#pragma once
// How far a rendered image is from the physics reference, over the pixels
// both cover (the tessellated silhouette and the analytic one differ by a
// pixel here and there; those are counted, not compared).
#include <cstddef>
#include <vector>

#include "core/image.h"

namespace snell::bench {

struct ImageError {
  double rms = 0;                    // linear RGB, over every compared channel
  double max = 0;                    // linear RGB, largest channel difference
  double deMean = 0;                 // CIEDE2000, mean over compared pixels
  double deP95 = 0;                  // CIEDE2000, 95th percentile (nearest rank)
  std::size_t compared = 0;          // pixels both cover
  std::size_t coverageMismatch = 0;  // pixels only one of them covers
};

// `rendered` covers a pixel where its alpha is above 0.5 (the methods write
// 1 over a clear of 0). The images must be the same size.
ImageError imageError(const Image& rendered, const Image& reference,
                      const std::vector<bool>& referenceCovers);

// The nearest-rank percentile (0 < p <= 100) of the values; 0 when empty.
double percentile(std::vector<double> values, double p);
// The median: of an even count, the mean of the middle two (where the 50th
// nearest-rank percentile is the lower one); 0 when empty.
double median(std::vector<double> values);

}  // namespace snell::bench
