#include "runner/unix_socket.h"

#include <fmt/format.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "core/errors.h"

namespace snell {
namespace {

sockaddr_un addressOf(const std::string& path) {
  sockaddr_un address{};
  address.sun_family = AF_UNIX;
  if (path.empty() || path.size() >= sizeof(address.sun_path))
    throw UsageError(
        fmt::format("{}: a socket path must have 1 to {} characters; give a shorter --socket", path,
                    sizeof(address.sun_path) - 1));
  std::memcpy(address.sun_path, path.c_str(), path.size() + 1);
  return address;
}

}  // namespace

UniqueFd::~UniqueFd() {
  if (fd_ >= 0) ::close(fd_);
}

UniqueFd& UniqueFd::operator=(UniqueFd&& other) noexcept {
  if (this != &other) {
    if (fd_ >= 0) ::close(fd_);
    fd_ = other.release();
  }
  return *this;
}

int UniqueFd::release() {
  const int fd = fd_;
  fd_ = -1;
  return fd;
}

UniqueFd listenAt(const std::string& path) {
  const sockaddr_un address = addressOf(path);
  struct stat existing {};
  if (lstat(path.c_str(), &existing) == 0) {
    if (!S_ISSOCK(existing.st_mode))
      throw UsageError(fmt::format("{}: exists and is not a socket; give another --socket", path));
    if (connectTo(path))
      throw UsageError(fmt::format(
          "{}: a server already answers here; stop it first, or give another --socket", path));
    // Only a socket nobody listens on is one left by a server that is gone
    // (any other failure, a full backlog say, may be a live server's).
    if (errno != ECONNREFUSED)
      throw UsageError(
          fmt::format("{}: a socket is here and did not refuse a connection ({}); "
                      "give another --socket",
                      path, std::strerror(errno)));
    ::unlink(path.c_str());
  }
  UniqueFd fd(::socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0));
  if (!fd) throw SetupError(fmt::format("cannot make a socket: {}", std::strerror(errno)));
  if (::bind(fd.get(), reinterpret_cast<const sockaddr*>(&address), sizeof(address)) != 0)
    throw SetupError(fmt::format("{}: cannot listen here: {}; give another --socket", path,
                                 std::strerror(errno)));
  // Connecting needs write permission on the socket file: its owner only
  // (the server also checks each client's user).
  if (::chmod(path.c_str(), 0600) != 0 || ::listen(fd.get(), 16) != 0) {
    const int error = errno;
    ::unlink(path.c_str());
    throw SetupError(fmt::format("{}: cannot listen here: {}; give another --socket", path,
                                 std::strerror(error)));
  }
  return fd;
}

UniqueFd connectTo(const std::string& path) {
  const sockaddr_un address = addressOf(path);
  UniqueFd fd(::socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0));
  if (!fd) return fd;
  if (::connect(fd.get(), reinterpret_cast<const sockaddr*>(&address), sizeof(address)) != 0) {
    const int error = errno;
    fd = UniqueFd();
    errno = error;
  }
  return fd;
}

bool peerIsThisUser(int fd, int* pid) {
  ucred peer{};
  socklen_t size = sizeof(peer);
  if (getsockopt(fd, SOL_SOCKET, SO_PEERCRED, &peer, &size) != 0) return false;
  if (pid) *pid = peer.pid;
  return peer.uid == getuid();
}

bool writeAll(int fd, const char* data, std::size_t size) {
  while (size > 0) {
    const ssize_t n = ::send(fd, data, size, MSG_NOSIGNAL);
    if (n < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    data += n;
    size -= static_cast<std::size_t>(n);
  }
  return true;
}

}  // namespace snell
