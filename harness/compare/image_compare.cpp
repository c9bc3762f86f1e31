#include "compare/image_compare.h"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "compare/image_io.h"
#include "compare/image_library.h"
#include "core/content_hash.h"
#include "core/errors.h"
#include "core/written_mark.h"

namespace snell {
namespace {

bool masked(const std::vector<PixelMask>& mask, std::size_t pixel) {
  return !mask.empty() && mask[pixel] != PixelMask::None;
}

}  // namespace

const char* imageVerdictName(ImageVerdict verdict) {
  switch (verdict) {
    case ImageVerdict::Pass:
      return "pass";
    case ImageVerdict::Warn:
      return "warn";
    case ImageVerdict::Fail:
      return "fail";
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

  SnellImageDifference r{};
  SnellImageError error;
  if (imageLibrary().compareRgba(observedMasked.pixels.data(), expected.pixels.data(),
                                 observed.width, observed.height,
                                 static_cast<float>(thresholds.fail),
                                 static_cast<float>(thresholds.warn), &r, &error) != SNELL_IMAGE_OK)
    throw SetupError(fmt::format("cannot compare with the {} image ({})", against, error.message));
  // OIIO averages over every pixel channel; re-scale to the compared ones.
  const double scale = result.compared ? double(pixels) / double(result.compared) : 0.0;
  result.maxError = r.maxError;
  result.meanError = r.meanError * scale;
  result.rmsError = r.rmsError * std::sqrt(scale);
  result.psnr = r.psnr;
  result.maxX = r.maxX;
  result.maxY = r.maxY;
  result.failed = r.failed;
  result.warned = r.warned;
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
  const std::size_t pixels = static_cast<std::size_t>(observed.width) * observed.height;
  // One value per pixel; masked pixels get -1, which the module draws grey.
  std::vector<float> difference(pixels);
  for (std::size_t p = 0; p < pixels; ++p) {
    double largest = 0;
    for (int c = 0; c < 4; ++c)
      largest = std::max(largest,
                         double(std::abs(observed.pixels[p * 4 + c] - expected.pixels[p * 4 + c])));
    difference[p] = masked(mask, p) ? -1.0f : static_cast<float>(std::min(1.0, largest / scale));
  }
  ContentHash hash;
  hash.add(std::string_view("heat map"));
  hash.add(std::string_view(imageWriterIdentity()));
  hash.add(observed.width);
  hash.add(observed.height);
  hash.addBytes(difference.data(), difference.size() * sizeof(float));
  const Digest digest = hash.finish();
  if (writtenFrom(path, digest)) return;  // this very file, written before
  std::filesystem::path temporary = path;
  temporary += fmt::format(".tmp{}{}", getpid(), path.extension().string());
  SnellImageError error;
  const bool written =
      imageLibrary().writeHeatMap(temporary.c_str(), difference.data(), observed.width,
                                  observed.height, &error) == SNELL_IMAGE_OK;
  keepWrittenImage(temporary, path, digest, written ? nullptr : error.message, " the heat map");
}

}  // namespace snell
