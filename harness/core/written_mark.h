#pragma once
// A file that snell wrote from known data carries the digest of that data
// (and of what wrote it) in an extended attribute, with the file's size and
// modification time at that moment. Writing the same data again can then be
// skipped: an image encoder is the costliest part of writing a picture, and
// a gate run again and again on the same driver renders the same pictures.
// A file changed since (its size or time differ), replaced, or on a file
// system without user attributes has no valid mark, and is written.
#include <filesystem>

#include "core/content_hash.h"

namespace snell {

// Whether `path` is the file written from data with `digest`, unchanged.
bool writtenFrom(const std::filesystem::path& path, const Digest& digest);

// Marks `path`, just written and not yet renamed into place (a rename keeps
// the mark, the size and the time), as written from `digest`. Best effort:
// without a mark the next run writes the file again.
void markWrittenFrom(const std::filesystem::path& path, const Digest& digest);

}  // namespace snell
