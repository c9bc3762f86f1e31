#pragma once
// A request's input and its answers as streams over a connected socket,
// waited on in ticks of a second, so that a server reading or writing
// still sees SIGINT/SIGTERM (the stream library retries a call that a
// signal interrupts) and a client that stops sending or reading without
// closing cannot hold the server forever. Each way a stream can end reads
// as its end (input) or as a failed write (answers); end() says which.
#include <array>
#include <chrono>
#include <csignal>
#include <optional>
#include <streambuf>

namespace snell {

enum class SocketEnd { NotYet, Closed, Stopped, Stalled, Failed };

class SocketInput : public std::streambuf {
 public:
  // `stop` is the flag a signal handler sets (InterruptFlag::flag());
  // the input ends as Stalled when the client sends nothing for `stallLimit`.
  SocketInput(int fd, const volatile std::sig_atomic_t* stop, std::chrono::seconds stallLimit);

  // A time by which the input must have arrived, however it trickles in
  // (the request header); nothing clears it.
  void setDeadline(std::optional<std::chrono::steady_clock::time_point> deadline) {
    deadline_ = deadline;
  }
  SocketEnd end() const { return end_; }

 protected:
  int_type underflow() override;
  // 1 when a read would not wait (see runner/ready_to_read.h), else 0.
  std::streamsize showmanyc() override;

 private:
  int fd_;
  const volatile std::sig_atomic_t* stop_;
  std::chrono::seconds stallLimit_;
  std::optional<std::chrono::steady_clock::time_point> deadline_;
  SocketEnd end_ = SocketEnd::NotYet;
  std::array<char, 1 << 16> buffer_;
};

class SocketOutput : public std::streambuf {
 public:
  SocketOutput(int fd, const volatile std::sig_atomic_t* stop, std::chrono::seconds stallLimit);
  ~SocketOutput() override;
  SocketOutput(const SocketOutput&) = delete;
  SocketOutput& operator=(const SocketOutput&) = delete;

  // NotYet while every write has gone out; else why one did not.
  SocketEnd end() const { return end_; }
  // For the last writes (the answers so far and the trailer, after a
  // signal too): no longer stopped by the flag, and let go after `limit`.
  void finishWithin(std::chrono::seconds limit) {
    stop_ = nullptr;
    stallLimit_ = limit;
  }

 protected:
  int_type overflow(int_type c) override;
  int sync() override;

 private:
  bool sendAll(const char* data, std::size_t size);

  int fd_;
  const volatile std::sig_atomic_t* stop_;
  std::chrono::seconds stallLimit_;
  SocketEnd end_ = SocketEnd::NotYet;
  std::array<char, 1 << 16> buffer_;
};

}  // namespace snell
