#pragma once
// Float RGBA images to and from files through OpenImageIO: EXR for
// comparison (lossless float), PNG for people. OpenImageIO is loaded on the
// first call (compare/image_library.h); when it cannot be, these throw
// SetupError saying which files were tried and what to do.
#include <filesystem>

#include "core/image.h"

namespace snell {

// Throws UsageError naming the file and what is wrong (missing, unreadable,
// truncated, not 4 channels) and what to do.
Image readImage(const std::filesystem::path& path);

// Writes to a temporary file beside `path` and renames it into place, so a
// reader never sees half a file. PNG output is clamped to [0, 1], sRGB-encoded.
void writeImageAtomically(const std::filesystem::path& path, const Image& image);

}  // namespace snell
