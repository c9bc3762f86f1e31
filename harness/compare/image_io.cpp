#include "compare/image_io.h"

#include <fmt/format.h>
#include <unistd.h>

#include <new>
#include <string>
#include <string_view>
#include <system_error>

#include "compare/image_library.h"
#include "core/content_hash.h"
#include "core/errors.h"
#include "core/written_mark.h"

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

void keepWrittenImage(const fs::path& temporary, const fs::path& path, const Digest& digest,
                      const char* failure, std::string_view what) {
  // OpenImageIO's PNG writer can report success for a file a full disk left
  // empty; marked and kept, it would be taken as up to date by every later
  // run. Only an empty file is caught here: one cut short part way is not.
  std::error_code status;
  const bool empty = !failure && fs::file_size(temporary, status) == 0;
  std::string why = failure ? failure
                    : empty ? "the file came out empty: is the disk full?"
                            : status.message();
  if (!failure && !empty && !status) {
    markWrittenFrom(temporary, digest);
    fs::rename(temporary, path, status);
    if (!status) return;
    why = status.message();
  }
  std::error_code ignored;
  fs::remove(temporary, ignored);
  throw SetupError(fmt::format("{}: cannot write{} ({})", path.string(), what, why));
}

void writeImageAtomically(const fs::path& path, const Image& image) {
  const bool png = path.extension() == ".png";
  ContentHash hash;
  hash.add(std::string_view("image file"));
  hash.add(std::string_view(imageWriterIdentity()));
  hash.add(png);
  hash.add(image.width);
  hash.add(image.height);
  hash.addBytes(image.pixels.data(), image.pixels.size() * sizeof(float));
  const Digest digest = hash.finish();
  if (writtenFrom(path, digest)) return;  // this very file, written before
  fs::path temporary = path;
  temporary += fmt::format(".tmp{}{}", getpid(), path.extension().string());
  SnellImageError error;
  const bool written =
      imageLibrary().write(temporary.c_str(), image.pixels.data(), image.width, image.height, 4,
                           png ? SNELL_IMAGE_SRGB8 : SNELL_IMAGE_FLOAT, &error) == SNELL_IMAGE_OK;
  keepWrittenImage(temporary, path, digest, written ? nullptr : error.message, "");
}

}  // namespace snell
