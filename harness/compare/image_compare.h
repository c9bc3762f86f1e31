#pragma once
// Image against image, in linear float, with masks: OpenImageIO's
// ImageBufAlgo::compare on the pixels that are not masked, and idiff's
// verdict: a channel off by more than `fail` fails the pixel, by more than
// `warn` warns; the comparison fails when more than `failPercent` percent of
// the compared pixels fail or any channel is off by more than `hardFail`.
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "core/image.h"
#include "core/manifest.h"
#include "core/pixel_mask.h"

namespace snell {

enum class ImageVerdict { Pass, Warn, Fail };
const char* imageVerdictName(ImageVerdict verdict);

struct ImageComparison {
  std::string against;  // "reference", "golden", "other-backend:A/B"
  ImageVerdict verdict = ImageVerdict::Pass;
  double maxError = 0, meanError = 0, rmsError = 0, psnr = 0;
  int maxX = 0, maxY = 0;
  std::size_t compared = 0, failed = 0, warned = 0;
  std::map<std::string, std::size_t> masked;  // by reason (PixelMask name)
  std::string problem;  // set when the images could not be compared (size mismatch)
};

// The `against` of a comparison between two backends' images:
// "other-backend:A/B" (runner/cross_api_check.h).
inline constexpr std::string_view kOtherBackendPrefix = "other-backend:";
inline bool isOtherBackendComparison(const ImageComparison& comparison) {
  return comparison.against.rfind(kOtherBackendPrefix, 0) == 0;
}

// `mask` may be empty (nothing masked); otherwise width * height entries.
ImageComparison compareImages(const std::string& against, const Image& observed,
                              const Image& expected, const std::vector<PixelMask>& mask,
                              const ImageTolerance& thresholds);

// A heat map of the largest channel difference per pixel (OpenImageIO's
// "inferno" map, 0 to `scale`), masked pixels in flat grey; PNG or EXR by
// the file name's extension. Throws SetupError when the file cannot be written.
void writeDifferenceHeatMap(const std::filesystem::path& path, const Image& observed,
                            const Image& expected, const std::vector<PixelMask>& mask,
                            double scale);

}  // namespace snell
