#include "core/watched_files.h"

#include <fmt/format.h>
#include <sys/stat.h>

#include <fstream>
#include <map>
#include <sstream>
#include <string_view>

#include "core/errors.h"

namespace snell {
namespace {

// The files whose code is mapped into this process: the executable
// mappings of /proc/self/maps. A line is "address perms offset dev inode
// path"; anonymous mappings have no path, and pseudo-files ([vdso], ...)
// are not files on disk. Data files a driver maps (Mesa's shader cache
// index, which grows as the cache fills) are not code and are left out. A
// mapped file whose name was removed shows as "PATH (deleted)": it is
// watched under PATH, which then no longer holds the loaded code.
// Path -> whether its name was removed since it was mapped.
std::map<std::string, bool> mappedFiles() {
  std::map<std::string, bool> paths;
  std::ifstream maps("/proc/self/maps");
  std::string line;
  while (std::getline(maps, line)) {
    std::istringstream fields(line);
    std::string address, perms, offset, device, inode;
    fields >> address >> perms >> offset >> device >> inode;
    std::string path;
    std::getline(fields >> std::ws, path);
    if (path.empty() || path.front() != '/' || perms.size() < 3 || perms[2] != 'x') continue;
    constexpr std::string_view deleted = " (deleted)";
    const bool removed = path.ends_with(deleted);
    if (removed) path.resize(path.size() - deleted.size());
    paths[path] = paths[path] || removed;
  }
  return paths;
}

bool sameTime(const timespec& a, const timespec& b) {
  return a.tv_sec == b.tv_sec && a.tv_nsec == b.tv_nsec;
}

}  // namespace

std::optional<WatchedFiles::Stamp> WatchedFiles::stampOf(const std::string& path) {
  struct stat status {};
  if (stat(path.c_str(), &status) != 0) return std::nullopt;
  return Stamp{path, status.st_dev, status.st_ino, status.st_size, status.st_mtim};
}

WatchedFiles WatchedFiles::ofThisProcess(const std::vector<std::string>& extra) {
  WatchedFiles watched;
  for (const std::string& path : extra) {
    std::optional<Stamp> stamp = stampOf(path);
    if (!stamp)
      throw UsageError(
          fmt::format("{}: cannot read this file to watch it; give a file that exists", path));
    watched.files_.push_back(std::move(*stamp));
  }
  for (const auto& [path, removed] : mappedFiles()) {
    // A name that is no file (an executable memfd, "/memfd:NAME (deleted)")
    // has nothing on disk to change. Code whose file was replaced (a
    // library reinstalled) while the process was starting is out of date
    // already.
    std::optional<Stamp> stamp = stampOf(path);
    if (!stamp) continue;
    if (removed) stamp->changedAlready = true;
    watched.files_.push_back(std::move(*stamp));
  }
  return watched;
}

std::optional<std::string> WatchedFiles::firstChanged() const {
  for (const Stamp& was : files_) {
    if (was.changedAlready) return was.path;
    const std::optional<Stamp> now = stampOf(was.path);
    if (!now || now->device != was.device || now->inode != was.inode || now->size != was.size ||
        !sameTime(now->modified, was.modified))
      return was.path;
  }
  return std::nullopt;
}

}  // namespace snell
