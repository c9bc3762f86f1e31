#include "runner/interrupt_flag.h"

#include <pthread.h>

#include <cerrno>

namespace snell {
namespace {

volatile std::sig_atomic_t received = 0;
pthread_t owner;

// The kernel hands a process's signal to any thread that does not block
// it: one of eval's pool threads or a driver's. The thread that made the
// flag may be blocked in a read or poll that only its own signal ends, so
// the signal is passed on to it (pthread_kill is async-signal-safe).
void record(int signal) {
  const int savedErrno = errno;
  received = signal;
  if (!pthread_equal(pthread_self(), owner)) pthread_kill(owner, signal);
  errno = savedErrno;
}

}  // namespace

InterruptFlag::InterruptFlag() {
  received = 0;
  owner = pthread_self();
  struct sigaction action {};
  action.sa_handler = record;
  sigemptyset(&action.sa_mask);
  action.sa_flags = 0;
  sigaction(SIGINT, &action, &previousInt_);
  sigaction(SIGTERM, &action, &previousTerm_);
}

InterruptFlag::~InterruptFlag() {
  sigaction(SIGINT, &previousInt_, nullptr);
  sigaction(SIGTERM, &previousTerm_, nullptr);
}

int InterruptFlag::signal() const { return received; }

const volatile std::sig_atomic_t* InterruptFlag::flag() const { return &received; }

}  // namespace snell
