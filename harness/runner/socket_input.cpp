#include "runner/socket_input.h"

#include <poll.h>
#include <sys/socket.h>

#include <cerrno>

namespace snell {

SocketInput::SocketInput(int fd, const volatile std::sig_atomic_t* stop,
                         std::chrono::seconds stallLimit)
    : fd_(fd), stop_(stop), stallLimit_(stallLimit) {}

SocketInput::int_type SocketInput::underflow() {
  if (gptr() < egptr()) return traits_type::to_int_type(*gptr());
  if (end_ != End::NotYet) return traits_type::eof();
  const auto waitingSince = std::chrono::steady_clock::now();
  for (;;) {
    if (stop_ && *stop_) {
      end_ = End::Stopped;
      return traits_type::eof();
    }
    pollfd readable{fd_, POLLIN, 0};
    const int ready = ::poll(&readable, 1, 1000);
    if (ready < 0 && errno != EINTR) {
      end_ = End::Failed;
      return traits_type::eof();
    }
    if (ready <= 0) {
      if (std::chrono::steady_clock::now() - waitingSince >= stallLimit_) {
        end_ = End::Stalled;
        return traits_type::eof();
      }
      continue;
    }
    const ssize_t n = ::recv(fd_, buffer_.data(), buffer_.size(), 0);
    if (n < 0 && (errno == EINTR || errno == EAGAIN)) continue;
    if (n <= 0) {
      end_ = n == 0 ? End::Closed : End::Failed;
      return traits_type::eof();
    }
    setg(buffer_.data(), buffer_.data(), buffer_.data() + n);
    return traits_type::to_int_type(*gptr());
  }
}

}  // namespace snell
