#pragma once
// Heat maps a person can read: the largest channel difference per pixel on
// a log colour scale from fail/1000 to above the fail threshold, with the
// colour bar and its scale (the fail threshold marked on it), masked pixels
// grey, and every pixel over the threshold circled while there are at most
// 500 of them. A failure of a dozen pixels in a 256x256 image is a handful
// of rings, where a linear map shows nothing; past 500 the rings would
// cover the errors they mark.
#include <string>
#include <vector>

#include "core/image.h"
#include "report/gnuplot_batch.h"

namespace snell {

struct HeatMapSummary {
  std::size_t overThreshold = 0;
  double maxError = 0;
};

// The largest channel difference over the pixels not masked: what the
// heat map shows at its top, and what a run records as an image
// comparison's max error.
double largestDifference(const Image& observed, const Image& expected,
                         const std::vector<bool>& masked);

// Adds the plot to `batch` and returns the PNG it will write. `masked` is
// empty or one flag per pixel (row 0 at the top).
std::filesystem::path addHeatMap(GnuplotBatch& batch, const std::string& title,
                                 const Image& observed, const Image& expected,
                                 const std::vector<bool>& masked, double failThreshold,
                                 HeatMapSummary& summary);

}  // namespace snell
