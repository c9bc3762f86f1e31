#include "compare/image_compare.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/errors.h"

namespace snell {
namespace {

OIIO::ImageBuf toBuffer(const Image& image) {
  OIIO::ImageSpec spec(image.width, image.height, 4, OIIO::TypeDesc::FLOAT);
  OIIO::ImageBuf buffer(spec);
  buffer.set_pixels(OIIO::ROI(0, image.width, 0, image.height, 0, 1, 0, 4), OIIO::TypeDesc::FLOAT,
                    image.pixels.data());
  return buffer;
}

bool masked(const std::vector<PixelMask>& mask, std::size_t pixel) {
  return !mask.empty() && mask[pixel] != PixelMask::None;
}

}  // namespace

const char* imageVerdictName(ImageVerdict verdict) {
  switch (verdict) {
    case ImageVerdict::Pass: return "pass";
    case ImageVerdict::Warn: return "warn";
    case ImageVerdict::Fail: return "fail";
  }
  return "?";
}

ImageComparison compareImages(const std::string& against, const Image& observed,
                              const Image& expected, const std::vector<PixelMask>& mask,
                              const ImageTolerance& thresholds) {
  ImageComparison result;
  result.against = against;
  if (observed.width != expected.width || observed.height != expected.height ||
      observed.pixels.size() != expected.pixels.size()) {
    result.verdict = ImageVerdict::Fail;
    result.problem = fmt::format("image is {}x{}, {} is {}x{}", observed.width, observed.height,
                                 against, expected.width, expected.height);
    return result;
  }
  const std::size_t pixels = static_cast<std::size_t>(observed.width) * observed.height;
  if (!mask.empty() && mask.size() != pixels)
    throw std::invalid_argument("mask size does not match the image");
  // Masked pixels are made equal in both, so OIIO counts them as agreeing;
  // they are then taken out of the counts and reported by reason.
  Image observedMasked = observed;
  for (std::size_t p = 0; p < pixels; ++p)
    if (masked(mask, p)) {
      std::copy_n(&expected.pixels[p * 4], 4, &observedMasked.pixels[p * 4]);
      ++result.masked[pixelMaskName(mask[p])];
    }
  std::size_t maskedCount = 0;
  for (const auto& [reason, n] : result.masked) maskedCount += n;
  result.compared = pixels - maskedCount;

  const OIIO::ImageBufAlgo::CompareResults r = OIIO::ImageBufAlgo::compare(
      toBuffer(observedMasked), toBuffer(expected), static_cast<float>(thresholds.fail),
      static_cast<float>(thresholds.warn));
  // r.error is not checked: OIIO sets it whenever a pixel fails, and the
  // sizes were checked above.
  // OIIO averages over every pixel channel; re-scale to the compared ones.
  const double scale = result.compared ? double(pixels) / double(result.compared) : 0.0;
  result.maxError = r.maxerror;
  result.meanError = r.meanerror * scale;
  result.rmsError = r.rms_error * std::sqrt(scale);
  result.psnr = r.PSNR;
  result.maxX = r.maxx;
  result.maxY = r.maxy;
  result.failed = r.nfail;
  result.warned = r.nwarn;
  const double failedPercent = result.compared ? 100.0 * result.failed / result.compared : 0.0;
  if (result.maxError > thresholds.hardFail || failedPercent > thresholds.failPercent)
    result.verdict = ImageVerdict::Fail;
  else if (result.failed > 0 || result.warned > 0)
    result.verdict = ImageVerdict::Warn;
  return result;
}

void writeDifferenceHeatMap(const std::filesystem::path& path, const Image& observed,
                            const Image& expected, const std::vector<PixelMask>& mask,
                            double scale) {
  Image difference(observed.width, observed.height);
  const std::size_t pixels = static_cast<std::size_t>(observed.width) * observed.height;
  for (std::size_t p = 0; p < pixels; ++p) {
    double largest = 0;
    for (int c = 0; c < 4; ++c)
      largest = std::max(largest, double(std::abs(observed.pixels[p * 4 + c] - expected.pixels[p * 4 + c])));
    const float value = masked(mask, p) ? -1.0f : static_cast<float>(std::min(1.0, largest / scale));
    std::fill_n(&difference.pixels[p * 4], 4, value);
  }
  OIIO::ImageBuf heat = OIIO::ImageBufAlgo::color_map(toBuffer(difference), 0, "inferno");
  // Masked pixels (value -1) in flat grey, so they cannot be read as "no error".
  for (std::size_t p = 0; p < pixels; ++p)
    if (difference.pixels[p * 4] < 0) {
      const float grey[3] = {0.5f, 0.5f, 0.5f};
      heat.setpixel(static_cast<int>(p % observed.width), static_cast<int>(p / observed.width), grey, 3);
    }
  if (!heat.write(path.string()))
    throw SetupError(fmt::format("{}: cannot write the heat map ({})", path.string(), heat.geterror()));
}

}  // namespace snell
