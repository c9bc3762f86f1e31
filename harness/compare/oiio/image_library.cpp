// snell_image_library: every OpenImageIO call snell makes, behind the C
// table of image_library_abi.h. Nothing but the entry point is exported, and
// no exception leaves a function: each is caught and turned into a status
// and a message.
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>
#include <OpenImageIO/oiioversion.h>

#include <cstdio>
#include <exception>
#include <memory>
#include <string>
#include <type_traits>

#include "compare/oiio/image_library_abi.h"

namespace {

SnellImageStatus report(SnellImageError* error, SnellImageStatus status,
                        const std::string& message) {
  std::snprintf(error->message, sizeof error->message, "%s", message.c_str());
  return status;
}

// Runs `body`, turning anything it throws into SNELL_IMAGE_FAILED.
template <typename Body>
SnellImageStatus guarded(SnellImageError* error, Body body) {
  try {
    return body();
  } catch (const std::exception& e) {
    return report(error, SNELL_IMAGE_FAILED, std::string("OpenImageIO failed: ") + e.what());
  } catch (...) {
    return report(error, SNELL_IMAGE_FAILED, "OpenImageIO failed with an unknown exception");
  }
}

// The PNGs are pictures for a person, a few per case and run: zlib's
// fastest level writes them in a fraction of the default's time (6), for
// files a little larger.
void fastPng(OIIO::ImageBuf& buffer) { buffer.specmod().attribute("png:compressionLevel", 1); }

// OpenImageIO stamps the time of writing into an EXR's capDate unless a
// DateTime is given: the same pixels would make different bytes on every
// write, and what is kept by the bytes of an image file (the decoded images
// of the oracle cache) would be kept anew by every run into a fresh --out,
// never to be read again. Empty, the file is the pixels alone.
void sameBytesForSamePixels(OIIO::ImageBuf& buffer) { buffer.specmod().attribute("DateTime", ""); }

OIIO::ImageBuf floatBuffer(const float* pixels, int width, int height, int channels) {
  OIIO::ImageBuf buffer(OIIO::ImageSpec(width, height, channels, OIIO::TypeDesc::FLOAT));
  buffer.set_pixels(OIIO::ROI(0, width, 0, height, 0, 1, 0, channels), OIIO::TypeDesc::FLOAT,
                    pixels);
  return buffer;
}

SnellImageStatus readRgba(const char* path, void* context, SnellImageAllocate allocate,
                          SnellImageError* error) {
  return guarded(error, [&] {
    // ImageInput, not ImageBuf: ImageBuf reads through OIIO's process-wide
    // cache, which would hand back a file's old contents after bless rewrote it.
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path);
    if (!in) return report(error, SNELL_IMAGE_BAD_FILE, "unreadable (" + OIIO::geterror() + ")");
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.nchannels != 4)
      return report(error, SNELL_IMAGE_BAD_FILE,
                    "has " + std::to_string(spec.nchannels) + " channels, RGBA (4) expected");
    float* pixels = allocate(context, spec.width, spec.height);
    if (!pixels)
      return report(error, SNELL_IMAGE_FAILED,
                    "no memory for " + std::to_string(spec.width) + "x" +
                        std::to_string(spec.height) + " pixels");
    if (!in->read_image(0, 0, 0, 4, OIIO::TypeDesc::FLOAT, pixels))
      return report(error, SNELL_IMAGE_BAD_FILE,
                    "unreadable, truncated or damaged (" + in->geterror() + ")");
    return SNELL_IMAGE_OK;
  });
}

SnellImageStatus write(const char* path, const float* pixels, int width, int height, int channels,
                       SnellImageEncoding encoding, SnellImageError* error) {
  return guarded(error, [&] {
    OIIO::ImageBuf buffer = floatBuffer(pixels, width, height, channels);
    const bool srgb8 = encoding == SNELL_IMAGE_SRGB8;
    if (srgb8) {
      buffer = OIIO::ImageBufAlgo::colorconvert(buffer, "linear", "sRGB");
      fastPng(buffer);
    } else {
      buffer.specmod().attribute("compression", "zip");
      sameBytesForSamePixels(buffer);
    }
    if (!buffer.write(path, srgb8 ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT))
      return report(error, SNELL_IMAGE_CANNOT_WRITE, buffer.geterror());
    return SNELL_IMAGE_OK;
  });
}

SnellImageStatus compareRgba(const float* a, const float* b, int width, int height, float fail,
                             float warn, SnellImageDifference* result, SnellImageError* error) {
  return guarded(error, [&] {
    const OIIO::ImageBufAlgo::CompareResults r = OIIO::ImageBufAlgo::compare(
        floatBuffer(a, width, height, 4), floatBuffer(b, width, height, 4), fail, warn);
    // r.error is not checked: OIIO sets it whenever a pixel fails; the
    // caller checks the sizes.
    result->meanError = r.meanerror;
    result->rmsError = r.rms_error;
    result->psnr = r.PSNR;
    result->maxError = r.maxerror;
    result->maxX = r.maxx;
    result->maxY = r.maxy;
    result->warned = r.nwarn;
    result->failed = r.nfail;
    return SNELL_IMAGE_OK;
  });
}

SnellImageStatus writeHeatMap(const char* path, const float* values, int width, int height,
                              SnellImageError* error) {
  return guarded(error, [&] {
    OIIO::ImageBuf heat =
        OIIO::ImageBufAlgo::color_map(floatBuffer(values, width, height, 1), 0, "inferno");
    // Masked pixels in flat grey, so they cannot be read as "no error".
    const float grey[3] = {0.5f, 0.5f, 0.5f};
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x)
        if (values[static_cast<std::size_t>(y) * width + x] < 0) heat.setpixel(x, y, grey, 3);
    fastPng(heat);
    sameBytesForSamePixels(heat);
    if (!heat.write(path)) return report(error, SNELL_IMAGE_CANNOT_WRITE, heat.geterror());
    return SNELL_IMAGE_OK;
  });
}

const SnellImageLibraryFunctions kFunctions = {
    SNELL_IMAGE_LIBRARY_ABI, OIIO_VERSION_STRING, readRgba, write, compareRgba, writeHeatMap,
};

}  // namespace

extern "C" __attribute__((visibility("default"))) const SnellImageLibraryFunctions*
snell_image_library(void) {
  return &kFunctions;
}

static_assert(std::is_same_v<decltype(&snell_image_library), SnellImageLibraryEntryPoint>,
              "the entry point's type is the one the loader casts to");
