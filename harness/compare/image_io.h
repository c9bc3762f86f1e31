#pragma once
// Float RGBA images to and from files through OpenImageIO: EXR for
// comparison (lossless float), PNG for people. OpenImageIO is loaded on the
// first call (compare/image_library.h); when it cannot be, these throw
// SetupError saying which files were tried and what to do.
#include <filesystem>
#include <string_view>

#include "core/content_hash.h"
#include "core/image.h"

namespace snell {

// Throws UsageError naming the file and what is wrong (missing, unreadable,
// truncated, not 4 channels) and what to do.
Image readImage(const std::filesystem::path& path);

// Writes to a temporary file beside `path` and renames it into place, so a
// reader never sees half a file. PNG output is clamped to [0, 1], sRGB-encoded.
void writeImageAtomically(const std::filesystem::path& path, const Image& image);

// The end of such a write: `temporary`, which the image module wrote (or
// failed to write: `failure` is its message, else null), is marked as made
// from `digest` and renamed to `path`; a failed, empty or unrenamed file is
// removed, and SetupError says "PATH: cannot write<what> (why)".
void keepWrittenImage(const std::filesystem::path& temporary, const std::filesystem::path& path,
                      const Digest& digest, const char* failure, std::string_view what);

}  // namespace snell
