#pragma once
// SIGINT and SIGTERM while a run is going: the handler only records the
// signal; the supervisor sees it, stops its workers and returns what
// finished, so the caller can still write the results and a summary.
// A second signal is the user's "now": the process says so on stderr and
// exits at once with 128 + the signal, without finishing what it writes.
#include <chrono>
#include <csignal>
#include <string>

namespace snell {

// Installs the handlers for its lifetime (without SA_RESTART, so a blocked
// poll() or read() of the thread that made it returns, whichever thread the
// signal reaches) and restores the previous ones after.
class InterruptFlag {
 public:
  InterruptFlag();
  ~InterruptFlag();
  InterruptFlag(const InterruptFlag&) = delete;
  InterruptFlag& operator=(const InterruptFlag&) = delete;

  // The signal received, or 0.
  int signal() const;
  // What the supervisor polls.
  const volatile std::sig_atomic_t* flag() const;

 private:
  struct sigaction previousInt_, previousTerm_;
};

// The signal a live InterruptFlag has received, or 0: for work that runs
// far from the flag (a sweep's driver children, a bench's methods) to stop
// at its next step.
int interruptReceived();

// "SIGINT", "SIGTERM", ...: a signal as messages name it.
std::string signalName(int signal);

// A signal within this time of the first is the same interrupt, not a
// second one (interrupt_flag.cpp says why).
inline constexpr std::chrono::milliseconds kSameInterrupt{250};

// The line stderr gets on the second signal (for the tests).
inline constexpr char kStoppedAtOnceMessage[] =
    "snell: a second interrupt: stopped at once; files being written may be incomplete\n";

}  // namespace snell
