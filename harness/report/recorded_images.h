#pragma once
// Whether the images in a run's --out folder are the ones its results
// recorded. A folder holds the images of the last run that wrote it: a
// stale copy (an earlier pipeline's, another job's) shown or compared as
// this run's contradicts its numbers. `report` leaves such images out and
// `merge` refuses to compare them across backends.
#include <filesystem>
#include <optional>
#include <vector>

#include "core/image.h"
#include "runner/case_result.h"

namespace snell {

// One flag per pixel of OUT/CASE/mask.exr (row 0 at the top); empty when
// there is no mask.
std::vector<bool> maskFlags(const std::filesystem::path& maskFile);
// The same from the mask image already read.
std::vector<bool> maskFlags(const Image& mask);

struct UnrecordedDifference {
  double there = 0;     // the images' largest difference from the reference
  double recorded = 0;  // the one the result recorded
};

// The largest difference of `rendered` from `reference` over the pixels
// not masked, where it is not the one `r` recorded against the reference
// (the same images give the same number, up to the float rounding of the
// comparison library's own difference); nothing when it is, or when `r`
// recorded none or the sizes differ (nothing can be told).
std::optional<UnrecordedDifference> differenceNotAsRecorded(const CaseResult& r,
                                                            const Image& rendered,
                                                            const Image& reference,
                                                            const std::vector<bool>& masked);

}  // namespace snell
