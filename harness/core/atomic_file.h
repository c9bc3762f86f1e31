#pragma once
// Result files are never left half-written under their final name: they are
// written beside it and renamed into place.
#include <sys/types.h>

#include <cstddef>
#include <filesystem>
#include <fstream>
#include <string>

namespace snell {

// The suffix of a results file while its run streams records into it.
inline constexpr const char* kPartialSuffix = ".partial";

// Streams records to "<path>.partial" as they come (flushed after each, so a
// crash keeps what was finished); finish() puts the final text at `path`
// atomically and removes the partial file. Left unfinished (the run stopped
// on an error), a partial file that holds records stays for inspection and
// --resume; one that holds none is removed, as it has nothing to resume and
// would only stand in the way of the next run.
class StreamingFile {
 public:
  explicit StreamingFile(std::filesystem::path path);
  ~StreamingFile();
  StreamingFile(const StreamingFile&) = delete;
  StreamingFile& operator=(const StreamingFile&) = delete;

  void writeLine(const std::string& line);
  void finish(const std::string& finalText);

 private:
  std::filesystem::path path_, partial_;
  std::ofstream out_;
  std::size_t lines_ = 0;
  bool finished_ = false;
};

// Writes the whole text to a temporary file and renames it over `path`.
void writeFileAtomically(const std::filesystem::path& path, const std::string& text);

// The temporary file writeFileAtomically writes beside `path` first.
std::filesystem::path temporaryPathFor(const std::filesystem::path& path);

// Removes the temporary files process `pid` left in `folder` (FILE.tmpPID,
// and FILE.tmpPID.EXT as the image module names them): a process killed
// while it wrote one never renamed it into place. Errors are ignored.
void removeTemporaryFilesOf(pid_t pid, const std::filesystem::path& folder);

}  // namespace snell
