#pragma once
// Files whose change makes a long-lived process out of date: the code it
// has loaded (its executable, the driver libraries: every file mapped
// executable in /proc/self/maps) and any others named. A process that answers requests
// for hours (`snell serve`) checks them before each request, so that a
// rebuilt driver or snell is never judged by code that is no longer on disk.
#include <sys/types.h>

#include <ctime>
#include <optional>
#include <string>
#include <vector>

namespace snell {

class WatchedFiles {
 public:
  // The files of code mapped into this process now (/proc/self/maps),
  // and `extra`, each as it is on disk now. Throws UsageError for an extra
  // file that cannot be read.
  static WatchedFiles ofThisProcess(const std::vector<std::string>& extra = {});

  // The first watched file that was replaced, rewritten, touched or
  // removed since the snapshot; nothing when all are as they were.
  std::optional<std::string> firstChanged() const;

  std::size_t size() const { return files_.size(); }

 private:
  struct Stamp {
    std::string path;
    dev_t device = 0;
    ino_t inode = 0;
    off_t size = 0;
    timespec modified{};
    bool changedAlready = false;  // mapped from a file since removed
  };
  static std::optional<Stamp> stampOf(const std::string& path);

  std::vector<Stamp> files_;
};

}  // namespace snell
