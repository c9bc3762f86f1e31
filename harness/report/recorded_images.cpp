#include "report/recorded_images.h"

#include <algorithm>
#include <cmath>

#include "compare/image_io.h"
#include "report/heat_map_chart.h"

namespace snell {

std::vector<bool> maskFlags(const std::filesystem::path& maskFile) {
  if (!std::filesystem::exists(maskFile)) return {};
  return maskFlags(readImage(maskFile));
}

std::vector<bool> maskFlags(const Image& mask) {
  std::vector<bool> flags(static_cast<std::size_t>(mask.width) * mask.height);
  for (std::size_t p = 0; p < flags.size(); ++p) flags[p] = mask.pixels[p * 4] != 0;
  return flags;
}

std::optional<UnrecordedDifference> differenceNotAsRecorded(const CaseResult& r,
                                                            const Image& rendered,
                                                            const Image& reference,
                                                            const std::vector<bool>& masked) {
  if (rendered.width != reference.width || rendered.height != reference.height) return {};
  for (const ImageComparison& c : r.images) {
    if (c.against != "reference" || !c.problem.empty()) continue;
    const double there = largestDifference(rendered, reference, masked);
    if (std::abs(there - c.maxError) <= 1e-4 * std::max(there, c.maxError) + 1e-7) return {};
    return UnrecordedDifference{there, c.maxError};
  }
  return {};
}

}  // namespace snell
