#include "bench/image_error.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "bench/ciede2000.h"

namespace snell::bench {

double percentile(std::vector<double> values, double p) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const auto rank = static_cast<std::size_t>(std::ceil(p / 100.0 * values.size()));
  return values[std::clamp<std::size_t>(rank, 1, values.size()) - 1];
}

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const std::size_t middle = values.size() / 2;
  return values.size() % 2 == 1 ? values[middle] : (values[middle - 1] + values[middle]) / 2.0;
}

ImageError imageError(const Image& rendered, const Image& reference,
                      const std::vector<bool>& referenceCovers) {
  if (rendered.width != reference.width || rendered.height != reference.height)
    throw std::logic_error("imageError: images of different sizes");
  ImageError out;
  double sumSquares = 0.0;
  std::vector<double> deltas;
  for (int y = 0; y < rendered.height; ++y) {
    for (int x = 0; x < rendered.width; ++x) {
      const bool inRendered = rendered.at(x, y)[3] > 0.5f;
      const bool inReference = referenceCovers[static_cast<std::size_t>(y) * rendered.width + x];
      if (inRendered != inReference) ++out.coverageMismatch;
      if (!inRendered || !inReference) continue;
      const float* a = rendered.at(x, y);
      const float* b = reference.at(x, y);
      for (int c = 0; c < 3; ++c) {
        const double d = static_cast<double>(a[c]) - b[c];
        sumSquares += d * d;
        out.max = std::max(out.max, std::abs(d));
      }
      deltas.push_back(
          ciede2000(linearSrgbToLab(a[0], a[1], a[2]), linearSrgbToLab(b[0], b[1], b[2])));
      ++out.compared;
    }
  }
  if (out.compared == 0) return out;
  out.rms = std::sqrt(sumSquares / (3.0 * out.compared));
  double sum = 0.0;
  for (double d : deltas) sum += d;
  out.deMean = sum / deltas.size();
  out.deP95 = percentile(deltas, 95.0);
  return out;
}

}  // namespace snell::bench
