#include "compare/image_io.h"

#include <fmt/format.h>
#include <unistd.h>

#include <new>

#include "compare/image_library.h"
#include "core/errors.h"

namespace snell {

namespace fs = std::filesystem;

namespace {

// SnellImageAllocate for an Image: sizes it, or answers NULL instead of
// throwing across the module boundary.
float* allocatePixels(void* context, int width, int height) {
  try {
    Image& image = *static_cast<Image*>(context);
    image = Image(width, height);
    return image.pixels.data();
  } catch (const std::bad_alloc&) {
    return nullptr;
  } catch (const std::length_error&) {
    return nullptr;
  }
}

}  // namespace

Image readImage(const fs::path& path) {
  if (!fs::exists(path)) throw UsageError(fmt::format("{}: missing", path.string()));
  Image image;
  SnellImageError error;
  switch (imageLibrary().readRgba(path.c_str(), &image, allocatePixels, &error)) {
    case SNELL_IMAGE_OK:
      return image;
    case SNELL_IMAGE_BAD_FILE:
      throw UsageError(fmt::format("{}: {}", path.string(), error.message));
    default:
      throw SetupError(fmt::format("{}: cannot read ({})", path.string(), error.message));
  }
}

void writeImageAtomically(const fs::path& path, const Image& image) {
  const bool png = path.extension() == ".png";
  fs::path temporary = path;
  temporary += fmt::format(".tmp{}{}", getpid(), path.extension().string());
  SnellImageError error;
  if (imageLibrary().write(temporary.c_str(), image.pixels.data(), image.width, image.height, 4,
                           png ? SNELL_IMAGE_SRGB8 : SNELL_IMAGE_FLOAT, &error) != SNELL_IMAGE_OK)
    throw SetupError(fmt::format("{}: cannot write ({})", path.string(), error.message));
  fs::rename(temporary, path);
}

}  // namespace snell
