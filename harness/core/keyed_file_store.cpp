#include "core/keyed_file_store.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <string>
#include <system_error>
#include <vector>

#include "core/whole_file.h"

namespace snell {
namespace fs = std::filesystem;

namespace {
constexpr const char* kExtension = ".result";
}  // namespace

fs::path KeyedFileStore::pathOf(const Digest& key) const {
  const std::string hex = key.hex();
  // Two levels, as ccache does: no folder grows past a few thousand files.
  return dir_ / hex.substr(0, 2) / (hex.substr(2) + kExtension);
}

std::optional<std::string> KeyedFileStore::read(const Digest& key) const {
  return readWholeFile(pathOf(key));
}

void KeyedFileStore::markUsed(const Digest& key) const {
  ::utimensat(AT_FDCWD, pathOf(key).c_str(), nullptr, 0);
}

bool KeyedFileStore::write(const Digest& key, const std::string& bytes) const {
  const fs::path path = pathOf(key);
  std::error_code error;
  fs::create_directories(path.parent_path(), error);
  if (error) return false;
  fs::path temporary = path;
  temporary += fmt::format(".tmp{}", ::getpid());
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) return false;
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.flush();
    if (!out) {
      out.close();
      fs::remove(temporary, error);
      return false;
    }
  }
  fs::rename(temporary, path, error);
  if (error) fs::remove(temporary, error);
  return !error;
}

StoreTrim trimKeyedFileStore(const fs::path& dir, std::uintmax_t maxBytes) {
  struct Entry {
    fs::path path;
    fs::file_time_type used;
    std::uintmax_t size;
  };
  std::vector<Entry> entries;
  StoreTrim trim;
  std::error_code error;
  for (auto it = fs::recursive_directory_iterator(dir, error);
       !error && it != fs::recursive_directory_iterator(); it.increment(error)) {
    if (!it->is_regular_file(error)) continue;
    const fs::path& path = it->path();
    const std::string name = path.filename().string();
    // A write that was interrupted leaves NAME.resultN.tmpPID; one older
    // than a day belongs to no running worker.
    if (name.find(".tmp") != std::string::npos) {
      const auto age = fs::file_time_type::clock::now() - it->last_write_time(error);
      if (!error && age > std::chrono::hours(24) && fs::remove(path, error)) ++trim.removed;
      continue;
    }
    if (path.extension() != kExtension) continue;
    entries.push_back({path, it->last_write_time(error), it->file_size(error)});
  }
  std::uintmax_t total = 0;
  for (const Entry& e : entries) total += e.size;
  std::sort(entries.begin(), entries.end(),
            [](const Entry& a, const Entry& b) { return a.used < b.used; });
  for (const Entry& e : entries) {
    if (total <= maxBytes) break;
    if (fs::remove(e.path, error)) {
      total -= e.size;
      ++trim.removed;
    }
  }
  trim.kept = total;
  return trim;
}

}  // namespace snell
