#include "bench/angle_error.h"

#include <cmath>

namespace snell::bench {

std::vector<AngleBin> errorByAngle(const Image& rendered, const ReferenceImage& reference,
                                   double binDeg) {
  std::vector<AngleBin> bins;
  if (reference.incidenceDeg.empty()) return bins;
  const int count = static_cast<int>(std::ceil(90.0 / binDeg));
  for (int k = 0; k < count; ++k) {
    const double from = k * binDeg;
    const double to = std::min(90.0, from + binDeg);
    std::vector<bool> inBin(reference.covered.size());
    for (std::size_t i = 0; i < inBin.size(); ++i) {
      const double angle = reference.incidenceDeg[i];
      // The last bin holds exactly 90 degrees too.
      inBin[i] = reference.covered[i] && angle >= from && (angle < to || k == count - 1);
    }
    // Pixels outside the bin count as "not covered by the reference": the
    // coverage mismatch of a bin says nothing, only its compared pixels do.
    bins.push_back({from, to, imageError(rendered, reference.color, inBin)});
  }
  return bins;
}

}  // namespace snell::bench
