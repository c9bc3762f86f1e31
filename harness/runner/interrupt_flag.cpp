#include "runner/interrupt_flag.h"

#include <pthread.h>
#include <time.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>

namespace snell {
namespace {

volatile std::sig_atomic_t received = 0;
pthread_t owner;
bool stderrIsTerminal = false;
// A signal this process passed on to the owner thread (below), which its
// handler takes as the same signal, not as a second one.
std::atomic<int> forwarded{0};
static_assert(std::atomic<int>::is_always_lock_free, "used in a signal handler");
// When the first signal came, in nanoseconds of CLOCK_MONOTONIC; 0 before.
std::atomic<long long> firstAt{0};
static_assert(std::atomic<long long>::is_always_lock_free, "used in a signal handler");

// clock_gettime is async-signal-safe (POSIX), and the monotonic clock does
// not jump with the wall clock.
long long monotonicNanoseconds() {
  timespec now{};
  clock_gettime(CLOCK_MONOTONIC, &now);
  return static_cast<long long>(now.tv_sec) * 1'000'000'000 + now.tv_nsec;
}

// coreutils `timeout -s INT` (and `kill` of a process group) sends the
// signal to the command and then to its group, which holds the command
// again: two within milliseconds, where a person's second Ctrl-C comes
// well after the first. Taken as a second interrupt, that one stopped the
// command at once, leaving what it was writing. A signal within
// kSameInterrupt of the first is the same interrupt; 0 means the first is
// still being recorded on another thread, which is the same burst too.
bool sameInterrupt() {
  const long long first = firstAt.load();
  return first == 0 ||
         monotonicNanoseconds() - first <
             std::chrono::duration_cast<std::chrono::nanoseconds>(kSameInterrupt).count();
}

void say(const char* text, std::size_t size) {
  const ssize_t ignored = ::write(STDERR_FILENO, text, size);
  (void)ignored;
}

constexpr char kFirstHint[] =
    "\nsnell: stopping after the work in hand; Ctrl-C again stops at once\n";

// The kernel hands a process's signal to any thread that does not block
// it: one of eval's pool threads or a driver's. The thread that made the
// flag may be blocked in a read or poll that only its own signal ends, so
// the signal is passed on to it (pthread_kill is async-signal-safe).
void record(int signal) {
  const int savedErrno = errno;
  const bool onOwner = pthread_equal(pthread_self(), owner);
  if (onOwner && forwarded.exchange(0) != 0) {
    errno = savedErrno;
    return;
  }
  if (received != 0) {
    if (sameInterrupt()) {
      errno = savedErrno;
      return;
    }
    say(kStoppedAtOnceMessage, sizeof kStoppedAtOnceMessage - 1);
    ::_exit(128 + signal);
  }
  firstAt.store(monotonicNanoseconds());
  received = signal;
  if (stderrIsTerminal) say(kFirstHint, sizeof kFirstHint - 1);
  if (!onOwner) {
    forwarded.store(1);
    pthread_kill(owner, signal);
  }
  errno = savedErrno;
}

}  // namespace

InterruptFlag::InterruptFlag() {
  received = 0;
  forwarded.store(0);
  firstAt.store(0);
  owner = pthread_self();
  stderrIsTerminal = ::isatty(STDERR_FILENO) == 1;
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

int interruptReceived() { return received; }

std::string signalName(int signal) {
  const char* abbreviation = sigabbrev_np(signal);
  return abbreviation ? std::string("SIG") + abbreviation : "signal " + std::to_string(signal);
}

const volatile std::sig_atomic_t* InterruptFlag::flag() const { return &received; }

}  // namespace snell
