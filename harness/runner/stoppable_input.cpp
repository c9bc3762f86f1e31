#include "runner/stoppable_input.h"

#include <unistd.h>

#include <cerrno>

namespace snell {

namespace {
constexpr std::size_t kBufferBytes = 1 << 16;
}

StoppableInputBuffer::StoppableInputBuffer(int fd, const volatile std::sig_atomic_t* stop)
    : fd_(fd), stop_(stop), buffer_(kBufferBytes) {}

StoppableInputBuffer::int_type StoppableInputBuffer::underflow() {
  if (gptr() < egptr()) return traits_type::to_int_type(*gptr());
  for (;;) {
    // Once stopped the input has ended, also for a file that could be read
    // on: what was read before is answered, nothing more is read.
    if (stop_ && *stop_ != 0) return traits_type::eof();
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

}  // namespace snell
