#include "runner/stoppable_input.h"

#include <poll.h>
#include <pthread.h>
#include <unistd.h>

#include <cerrno>

#include "runner/ready_to_read.h"

namespace snell {

namespace {

constexpr std::size_t kBufferBytes = 1 << 16;

// SIGINT and SIGTERM blocked for its lifetime, on this thread.
class BlockedStopSignals {
 public:
  BlockedStopSignals() {
    sigset_t stops;
    sigemptyset(&stops);
    sigaddset(&stops, SIGINT);
    sigaddset(&stops, SIGTERM);
    pthread_sigmask(SIG_BLOCK, &stops, &previous_);
  }
  ~BlockedStopSignals() { pthread_sigmask(SIG_SETMASK, &previous_, nullptr); }
  BlockedStopSignals(const BlockedStopSignals&) = delete;
  BlockedStopSignals& operator=(const BlockedStopSignals&) = delete;
  const sigset_t& previous() const { return previous_; }

 private:
  sigset_t previous_;
};

}  // namespace

StoppableInputBuffer::StoppableInputBuffer(int fd, const volatile std::sig_atomic_t* stop)
    : fd_(fd), stop_(stop), buffer_(kBufferBytes) {}

StoppableInputBuffer::int_type StoppableInputBuffer::underflow() {
  if (gptr() < egptr()) return traits_type::to_int_type(*gptr());
  // The stop signals are let in only while waiting for input (ppoll takes
  // the old mask atomically): one that comes between the check of the flag
  // and the wait ends the wait at once, where a read() would block on a
  // quiet pipe until more input came.
  const BlockedStopSignals blocked;
  for (;;) {
    // Once stopped the input has ended, also for a file that could be read
    // on: what was read before is answered, nothing more is read.
    if (stop_ && *stop_ != 0) return traits_type::eof();
    pollfd ready{fd_, POLLIN, 0};
    if (::ppoll(&ready, 1, nullptr, &blocked.previous()) < 0) {
      if (errno == EINTR) continue;
      error_ = errno;
      return traits_type::eof();
    }
    const ssize_t got = ::read(fd_, buffer_.data(), buffer_.size());
    if (got > 0) {
      setg(buffer_.data(), buffer_.data(), buffer_.data() + got);
      return traits_type::to_int_type(buffer_[0]);
    }
    if (got == 0) return traits_type::eof();
    if (errno == EINTR) continue;
    error_ = errno;
    return traits_type::eof();
  }
}

std::streamsize StoppableInputBuffer::showmanyc() {
  // Once stopped a read ends at once.
  return (stop_ && *stop_ != 0) || readsWithoutWaiting(fd_) ? 1 : 0;
}

}  // namespace snell
