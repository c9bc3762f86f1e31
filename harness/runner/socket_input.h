#pragma once
// A request's input as a stream, read from a connected socket in ticks of
// a second, so that a server reading it still sees SIGINT/SIGTERM (the
// stream library retries a read that a signal interrupts) and a client
// that stops sending without closing cannot hold the server forever. Each
// way the input can end reads as the end of the stream; end() says which.
#include <array>
#include <chrono>
#include <csignal>
#include <streambuf>

namespace snell {

class SocketInput : public std::streambuf {
 public:
  enum class End { NotYet, Closed, Stopped, Stalled, Failed };

  // `stop` is the flag a signal handler sets (InterruptFlag::flag()).
  SocketInput(int fd, const volatile std::sig_atomic_t* stop, std::chrono::seconds stallLimit);

  // How long the client may send nothing before the input ends as Stalled.
  void setStallLimit(std::chrono::seconds limit) { stallLimit_ = limit; }
  End end() const { return end_; }

 protected:
  int_type underflow() override;

 private:
  int fd_;
  const volatile std::sig_atomic_t* stop_;
  std::chrono::seconds stallLimit_;
  End end_ = End::NotYet;
  std::array<char, 1 << 16> buffer_;
};

}  // namespace snell
