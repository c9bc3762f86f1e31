#include "compare/image_io.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>
#include <fmt/format.h>
#include <unistd.h>

#include "core/errors.h"

namespace snell {

namespace fs = std::filesystem;

Image readImage(const fs::path& path) {
  if (!fs::exists(path)) throw UsageError(fmt::format("{}: missing", path.string()));
  // ImageInput, not ImageBuf: ImageBuf reads through OIIO's process-wide
  // cache, which would hand back a file's old contents after bless rewrote it.
  std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path.string());
  if (!in)
    throw UsageError(fmt::format("{}: unreadable ({})", path.string(), OIIO::geterror()));
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.nchannels != 4)
    throw UsageError(fmt::format("{}: has {} channels, RGBA (4) expected", path.string(), spec.nchannels));
  Image image(spec.width, spec.height);
  if (!in->read_image(0, 0, 0, 4, OIIO::TypeDesc::FLOAT, image.pixels.data()))
    throw UsageError(fmt::format("{}: unreadable, truncated or damaged ({})", path.string(),
                                 in->geterror()));
  return image;
}

void writeImageAtomically(const fs::path& path, const Image& image) {
  OIIO::ImageSpec spec(image.width, image.height, 4, OIIO::TypeDesc::FLOAT);
  OIIO::ImageBuf buffer(spec);
  buffer.set_pixels(OIIO::ROI(0, image.width, 0, image.height, 0, 1, 0, 4), OIIO::TypeDesc::FLOAT,
                    image.pixels.data());
  const bool png = path.extension() == ".png";
  if (png) buffer = OIIO::ImageBufAlgo::colorconvert(buffer, "linear", "sRGB");
  fs::path temporary = path;
  temporary += fmt::format(".tmp{}{}", getpid(), path.extension().string());
  if (!png) buffer.specmod().attribute("compression", "zip");
  if (!buffer.write(temporary.string(), png ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT))
    throw SetupError(fmt::format("{}: cannot write ({})", path.string(), buffer.geterror()));
  fs::rename(temporary, path);
}

}  // namespace snell
