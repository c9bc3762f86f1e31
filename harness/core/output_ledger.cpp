#include "core/output_ledger.h"

#include <sys/stat.h>

#include <chrono>
#include <fstream>
#include <system_error>

#include "core/atomic_file.h"

namespace snell {

namespace fs = std::filesystem;

namespace {

// A file written in the same tick of the file system's coarse clock as the
// snapshot may show no change: only a file unchanged since well before
// the run is taken as the last run's and removed (the safe side is a stale
// file kept, never an output of this run lost).
constexpr std::int64_t kSettledNs = 2'000'000'000;

std::map<std::string, OutputLedger::Seen> snapshot(const fs::path& folder) {
  std::map<std::string, OutputLedger::Seen> files;
  std::error_code error;
  for (fs::recursive_directory_iterator it(folder, error), end; !error && it != end;
       it.increment(error)) {
    struct stat info {};
    if (::lstat(it->path().c_str(), &info) != 0 || !S_ISREG(info.st_mode)) continue;
    if (it->path().filename() == OutputLedger::kFileName) continue;
    files[it->path().lexically_relative(folder).generic_string()] = {
        static_cast<std::uintmax_t>(info.st_ino), static_cast<std::uintmax_t>(info.st_size),
        static_cast<std::int64_t>(info.st_mtim.tv_sec) * 1'000'000'000 + info.st_mtim.tv_nsec};
  }
  return files;
}

std::int64_t nowNs() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
             std::chrono::system_clock::now().time_since_epoch())
      .count();
}

}  // namespace

OutputLedger::OutputLedger(fs::path folder)
    : folder_(std::move(folder)), before_(snapshot(folder_)), startNs_(nowNs()) {}

std::vector<fs::path> OutputLedger::settle() const {
  const std::map<std::string, Seen> after = snapshot(folder_);
  std::vector<fs::path> removed;
  std::ifstream last(folder_ / kFileName);
  for (std::string line; std::getline(last, line);) {
    // Only plain relative names below the folder: the ledger is a file a
    // user could edit.
    const fs::path name = fs::path(line).lexically_normal();
    if (line.empty() || name.is_absolute() || name.empty() || *name.begin() == "..") continue;
    const auto now = after.find(name.generic_string());
    const auto then = before_.find(name.generic_string());
    if (now == after.end() || then == before_.end() || !(now->second == then->second)) continue;
    if (now->second.modifiedNs > startNs_ - kSettledNs) continue;
    std::error_code error;
    if (fs::remove(folder_ / name, error)) removed.push_back(folder_ / name);
  }
  // This run's: what appeared or changed since the snapshot.
  std::string list;
  for (const auto& [name, seen] : after) {
    const auto then = before_.find(name);
    if (then == before_.end() || !(then->second == seen)) list += name + "\n";
  }
  writeFileAtomically(folder_ / kFileName, list);
  return removed;
}

}  // namespace snell
