#include "core/written_mark.h"

#include <sys/stat.h>
#include <sys/xattr.h>

#include <cstdint>
#include <cstring>

namespace snell {
namespace {

constexpr const char* kAttribute = "user.snell.written-from";

struct Mark {
  Digest digest;
  std::int64_t size;
  std::int64_t seconds;
  std::int64_t nanoseconds;
};

bool stamp(const std::filesystem::path& path, Mark& mark) {
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0 || !S_ISREG(info.st_mode)) return false;
  mark.size = info.st_size;
  mark.seconds = info.st_mtim.tv_sec;
  mark.nanoseconds = info.st_mtim.tv_nsec;
  return true;
}

}  // namespace

bool writtenFrom(const std::filesystem::path& path, const Digest& digest) {
  Mark stored{};
  if (::getxattr(path.c_str(), kAttribute, &stored, sizeof stored) !=
      static_cast<ssize_t>(sizeof stored))
    return false;
  Mark now{};
  if (!stamp(path, now)) return false;
  return stored.digest == digest && stored.size == now.size && stored.seconds == now.seconds &&
         stored.nanoseconds == now.nanoseconds;
}

void markWrittenFrom(const std::filesystem::path& path, const Digest& digest) {
  Mark mark{};
  mark.digest = digest;
  if (stamp(path, mark)) ::setxattr(path.c_str(), kAttribute, &mark, sizeof mark, 0);
}

}  // namespace snell
