#pragma once
// A file's bytes in one read (its size first, then read() until done):
// reading through a stream iterator, one character per call, was a visible
// cost for files of megabytes (kept results, rendered images).
#include <filesystem>
#include <optional>
#include <string>

namespace snell {

// Nothing when the file is missing, unreadable or changed size while read.
std::optional<std::string> readWholeFile(const std::filesystem::path& path);

}  // namespace snell
