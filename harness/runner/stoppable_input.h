#pragma once
// A file descriptor read as a std::istream that a signal can end: a read
// blocked on a pipe whose writer is idle returns once the stop flag is set
// (libstdc++'s own file streams retry a read that a signal interrupted, so
// `snell eval` reading a quiet pipe would wait on after Ctrl-C).
#include <csignal>
#include <cstddef>
#include <streambuf>
#include <vector>

namespace snell {

class StoppableInputBuffer : public std::streambuf {
 public:
  // Reads `fd` (not closed here). Once `stop` is non-zero the input ends:
  // a read the signal interrupted, and every later one, gives end of file.
  StoppableInputBuffer(int fd, const volatile std::sig_atomic_t* stop);

  // The errno of a read that failed (0: none), which ended the input.
  int error() const { return error_; }

 protected:
  int_type underflow() override;
  // 1 when a read would not wait (see runner/ready_to_read.h), else 0.
  std::streamsize showmanyc() override;

 private:
  int fd_;
  const volatile std::sig_atomic_t* stop_;
  std::vector<char> buffer_;
  int error_ = 0;
};

}  // namespace snell
