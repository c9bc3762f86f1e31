#include "core/atomic_file.h"

#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <system_error>
#include <vector>

#include "core/errors.h"

namespace snell {

namespace fs = std::filesystem;

StreamingFile::StreamingFile(fs::path path) : path_(std::move(path)) {
  partial_ = path_;
  partial_ += kPartialSuffix;
  out_.open(partial_, std::ios::binary | std::ios::trunc);
  if (!out_)
    throw UsageError(fmt::format("{}: cannot write here; check the folder exists and is writable",
                                 partial_.string()));
}

StreamingFile::~StreamingFile() {
  if (finished_ || lines_ > 0) return;
  out_.close();
  std::error_code ignored;
  fs::remove(partial_, ignored);
}

void StreamingFile::writeLine(const std::string& line) {
  out_ << line << '\n';
  out_.flush();
  ++lines_;
}

void StreamingFile::finish(const std::string& finalText) {
  out_.close();
  writeFileAtomically(path_, finalText);
  finished_ = true;
  fs::remove(partial_);
}

fs::path temporaryPathFor(const fs::path& path) {
  fs::path temporary = path;
  temporary += fmt::format(".tmp{}", getpid());
  return temporary;
}

void removeTemporaryFilesOf(pid_t pid, const fs::path& folder) {
  const std::string mark = fmt::format(".tmp{}", pid);
  std::error_code error;
  std::vector<fs::path> left;
  for (fs::directory_iterator it(folder, error), end; !error && it != end; it.increment(error)) {
    const std::string name = it->path().filename().string();
    const std::size_t at = name.rfind(mark);
    // The mark ends the name or comes before the extension kept after it.
    if (at == std::string::npos || at == 0) continue;
    const std::size_t after = at + mark.size();
    if (after == name.size() || name[after] == '.') left.push_back(it->path());
  }
  for (const fs::path& path : left) fs::remove(path, error);
}

void writeFileAtomically(const fs::path& path, const std::string& text) {
  const fs::path temporary = temporaryPathFor(path);
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out)
      throw UsageError(fmt::format("{}: cannot write here; check the folder exists and is writable",
                                   path.string()));
    out << text;
    out.flush();
    if (!out) {
      const int failure = errno;
      out.close();
      std::error_code ignored;
      fs::remove(temporary, ignored);
      throw UsageError(
          fmt::format("{}: write failed ({}); free some space or name a file elsewhere",
                      path.string(), std::strerror(failure)));
    }
  }
  std::error_code error;
  fs::rename(temporary, path, error);
  if (error) {
    fs::remove(temporary);
    throw UsageError(fmt::format("{}: cannot be written ({}); name a file in a writable folder",
                                 path.string(), error.message()));
  }
}

}  // namespace snell
