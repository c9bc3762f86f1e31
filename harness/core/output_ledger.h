#pragma once
// The files a command wrote into a folder of its own (a sweep's --out, a
// bench ladder's folder), listed there in .snell-outputs. When the command
// ends, the files of its last run there that it did not write again are
// removed: the charts and data of a run with other options (another
// backend, other sizes) would otherwise stay beside the new results and
// contradict them. A file it never listed is the user's, and never touched.
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace snell {

class OutputLedger {
 public:
  static constexpr const char* kFileName = ".snell-outputs";

  // Notes what the folder holds now: what changes from here on is this
  // run's.
  explicit OutputLedger(std::filesystem::path folder);

  // Once the command's outputs are written: removes the files the last run
  // listed that this run did not write, lists this run's, and returns what
  // it removed.
  std::vector<std::filesystem::path> settle() const;

  // A file's identity and last write, as the folder held it.
  struct Seen {
    std::uintmax_t inode = 0;
    std::uintmax_t size = 0;
    std::int64_t modifiedNs = 0;
    bool operator==(const Seen&) const = default;
  };

 private:
  std::filesystem::path folder_;
  std::map<std::string, Seen> before_;  // by name relative to the folder
  std::int64_t startNs_ = 0;
};

}  // namespace snell
