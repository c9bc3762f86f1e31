#pragma once
// The few Unix-domain stream socket calls `snell serve` and `snell eval
// --server` share, with their failures turned into messages.
#include <cstddef>
#include <string>

namespace snell {

// An owned file descriptor, closed when it goes out of scope.
class UniqueFd {
 public:
  UniqueFd() = default;
  explicit UniqueFd(int fd) : fd_(fd) {}
  ~UniqueFd();
  UniqueFd(UniqueFd&& other) noexcept : fd_(other.release()) {}
  UniqueFd& operator=(UniqueFd&& other) noexcept;
  UniqueFd(const UniqueFd&) = delete;
  UniqueFd& operator=(const UniqueFd&) = delete;

  int get() const { return fd_; }
  explicit operator bool() const { return fd_ >= 0; }
  int release();

 private:
  int fd_ = -1;
};

// A socket listening at `path`. A socket file left there by a server that
// is gone is replaced; a live server there, or a file that is not a
// socket, is a UsageError (nothing is removed). Throws SetupError when the
// socket cannot be made.
UniqueFd listenAt(const std::string& path);

// A connection to the server at `path`, or an empty fd with errno set.
UniqueFd connectTo(const std::string& path);

// Whether the process at the other end of a connected socket runs as this
// process's user (SO_PEERCRED); its pid goes to `pid` when given.
bool peerIsThisUser(int fd, int* pid = nullptr);

// Writes all of `size` bytes; false when the peer is gone (no SIGPIPE).
bool writeAll(int fd, const char* data, std::size_t size);

}  // namespace snell
