#include "core/keyed_file_store.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <string>
#include <string_view>
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

namespace {

bool isHex(std::string_view text) {
  return !text.empty() && text.find_first_not_of("0123456789abcdef") == std::string_view::npos;
}

// The store's own files, as pathOf and write name them: a folder of two hex
// digits, and in it HEX.result, or HEX.result.tmpPID while it is written.
// The store may be pointed at a folder that holds other files too (a CI
// cache folder, a project): the trim touches nothing else.
enum class StoreFile { Foreign, Entry, Temporary };
StoreFile kindOf(const std::string& folder, const std::string& name) {
  if (folder.size() != 2 || !isHex(folder)) return StoreFile::Foreign;
  const auto dot = name.find('.');
  if (dot == std::string::npos || !isHex(std::string_view(name).substr(0, dot)))
    return StoreFile::Foreign;
  const std::string_view rest = std::string_view(name).substr(dot);
  if (rest == kExtension) return StoreFile::Entry;
  const std::string_view tmp = ".tmp";
  const std::string_view extension = kExtension;
  if (rest.substr(0, extension.size()) == extension &&
      rest.substr(extension.size(), tmp.size()) == tmp &&
      rest.size() > extension.size() + tmp.size() &&
      rest.substr(extension.size() + tmp.size()).find_first_not_of("0123456789") ==
          std::string_view::npos)
    return StoreFile::Temporary;
  return StoreFile::Foreign;
}

}  // namespace

StoreTrim trimKeyedFileStore(const fs::path& dir, std::uintmax_t maxBytes) {
  struct Entry {
    fs::path path;
    fs::file_time_type used;
    std::uintmax_t size;
  };
  std::vector<Entry> entries;
  StoreTrim trim;
  std::error_code error;
  for (auto folder = fs::directory_iterator(dir, error);
       !error && folder != fs::directory_iterator(); folder.increment(error)) {
    if (!folder->is_directory(error)) continue;
    const std::string folderName = folder->path().filename().string();
    std::error_code inner;
    for (auto it = fs::directory_iterator(folder->path(), inner);
         !inner && it != fs::directory_iterator(); it.increment(inner)) {
      // Each file's own error: one another trim removed meanwhile is passed
      // over, and the folder's other files are still read.
      std::error_code file;
      if (!it->is_regular_file(file)) continue;
      const fs::path& path = it->path();
      switch (kindOf(folderName, path.filename().string())) {
        case StoreFile::Foreign:
          break;
        case StoreFile::Temporary: {
          // A write that was interrupted; one older than a day belongs to
          // no running process.
          const auto age = fs::file_time_type::clock::now() - it->last_write_time(file);
          if (!file && age > std::chrono::hours(24) && fs::remove(path, file)) ++trim.removed;
          break;
        }
        case StoreFile::Entry: {
          const auto used = it->last_write_time(file);
          const auto size = file ? 0 : it->file_size(file);
          if (!file) entries.push_back({path, used, size});
          break;
        }
      }
    }
  }
  std::uintmax_t total = 0;
  for (const Entry& e : entries) total += e.size;
  std::sort(entries.begin(), entries.end(),
            [](const Entry& a, const Entry& b) { return a.used < b.used; });
  for (const Entry& e : entries) {
    if (total <= maxBytes) break;
    // An entry another process trimmed at the same moment is gone all the
    // same: counted as gone, or two trims at once would each remove what
    // the other already had.
    if (fs::remove(e.path, error)) ++trim.removed;
    if (!error) total -= e.size;
  }
  trim.kept = total;
  return trim;
}

}  // namespace snell
