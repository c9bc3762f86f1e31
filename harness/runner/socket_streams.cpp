#include "runner/socket_streams.h"

#include <poll.h>
#include <sys/socket.h>

#include <cerrno>

#include "runner/ready_to_read.h"

namespace snell {
namespace {

using Clock = std::chrono::steady_clock;

// Waits up to a second for `events` on `fd`: 1 ready, 0 not yet, -1 failed.
int waitFor(int fd, short events) {
  pollfd waiting{fd, events, 0};
  const int ready = ::poll(&waiting, 1, 1000);
  if (ready < 0) return errno == EINTR ? 0 : -1;
  return ready;
}

}  // namespace

SocketInput::SocketInput(int fd, const volatile std::sig_atomic_t* stop,
                         std::chrono::seconds stallLimit)
    : fd_(fd), stop_(stop), stallLimit_(stallLimit) {}

SocketInput::int_type SocketInput::underflow() {
  if (gptr() < egptr()) return traits_type::to_int_type(*gptr());
  if (end_ != SocketEnd::NotYet) return traits_type::eof();
  const auto waitingSince = Clock::now();
  const auto endAs = [&](SocketEnd why) {
    end_ = why;
    return traits_type::eof();
  };
  for (;;) {
    if (stop_ && *stop_) return endAs(SocketEnd::Stopped);
    const auto now = Clock::now();
    if (now - waitingSince >= stallLimit_ || (deadline_ && now >= *deadline_))
      return endAs(SocketEnd::Stalled);
    const int ready = waitFor(fd_, POLLIN);
    if (ready < 0) return endAs(SocketEnd::Failed);
    if (ready == 0) continue;
    const ssize_t n = ::recv(fd_, buffer_.data(), buffer_.size(), MSG_DONTWAIT);
    if (n < 0 && (errno == EINTR || errno == EAGAIN)) continue;
    if (n <= 0) return endAs(n == 0 ? SocketEnd::Closed : SocketEnd::Failed);
    setg(buffer_.data(), buffer_.data(), buffer_.data() + n);
    return traits_type::to_int_type(*gptr());
  }
}

std::streamsize SocketInput::showmanyc() {
  // An input that has ended, or that a stop ends, reads at once.
  return end_ != SocketEnd::NotYet || (stop_ && *stop_) || readsWithoutWaiting(fd_) ? 1 : 0;
}

SocketOutput::SocketOutput(int fd, const volatile std::sig_atomic_t* stop,
                           std::chrono::seconds stallLimit)
    : fd_(fd), stop_(stop), stallLimit_(stallLimit) {
  setp(buffer_.data(), buffer_.data() + buffer_.size());
}

// This class's own sync (a virtual call in a destructor binds statically).
SocketOutput::~SocketOutput() { SocketOutput::sync(); }

bool SocketOutput::sendAll(const char* data, std::size_t size) {
  // A signal stops only a write that waits: what the socket takes at once
  // is sent (the answers so far, as the client expects them).
  auto progressAt = Clock::now();
  while (size > 0) {
    if (end_ != SocketEnd::NotYet) return false;
    const ssize_t n = ::send(fd_, data, size, MSG_NOSIGNAL | MSG_DONTWAIT);
    if (n > 0) {
      data += n;
      size -= static_cast<std::size_t>(n);
      progressAt = Clock::now();
      continue;
    }
    if (n < 0 && errno != EINTR && errno != EAGAIN) {
      end_ = errno == EPIPE || errno == ECONNRESET ? SocketEnd::Closed : SocketEnd::Failed;
      return false;
    }
    if (stop_ && *stop_) {
      end_ = SocketEnd::Stopped;
    } else if (Clock::now() - progressAt >= stallLimit_) {
      end_ = SocketEnd::Stalled;
    } else if (waitFor(fd_, POLLOUT) < 0) {
      end_ = SocketEnd::Failed;
    }
  }
  return true;
}

SocketOutput::int_type SocketOutput::overflow(int_type c) {
  if (sync() != 0) return traits_type::eof();
  if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
  *pptr() = traits_type::to_char_type(c);
  pbump(1);
  return c;
}

int SocketOutput::sync() {
  const std::size_t pending = static_cast<std::size_t>(pptr() - pbase());
  const bool sent = pending == 0 || sendAll(pbase(), pending);
  setp(buffer_.data(), buffer_.data() + buffer_.size());
  return sent ? 0 : -1;
}

}  // namespace snell
