#include "runner/interrupt_flag.h"

namespace snell {
namespace {

volatile std::sig_atomic_t received = 0;

void record(int signal) { received = signal; }

}  // namespace

InterruptFlag::InterruptFlag() {
  received = 0;
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
