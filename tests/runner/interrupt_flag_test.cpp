// The first SIGINT/SIGTERM is recorded for the command to stop in its own
// time; a second ends the process at once, saying so, with 128 + the
// signal. A signal the handler passes on to the flag's own thread is the
// same signal, not a second one, and so is one that comes within
// kSameInterrupt of the first (coreutils `timeout` sends two).
#include "runner/interrupt_flag.h"

#include <gtest/gtest.h>
#include <pthread.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <thread>

namespace snell {
namespace {

class InterruptFlagDeath : public ::testing::Test {
 protected:
  void SetUp() override { GTEST_FLAG_SET(death_test_style, "threadsafe"); }
};

// Long enough after the first signal for the next to be a second interrupt.
void waitPastTheFirst() {
  std::this_thread::sleep_for(kSameInterrupt + std::chrono::milliseconds(50));
}

TEST_F(InterruptFlagDeath, TheFirstSignalIsRecordedAndTheSecondEndsTheProcessAtOnce) {
  EXPECT_EXIT(
      {
        const InterruptFlag interrupt;
        std::raise(SIGINT);
        if (interrupt.signal() != SIGINT || *interrupt.flag() != SIGINT) ::_exit(3);
        waitPastTheFirst();
        std::raise(SIGINT);
        ::_exit(4);  // not reached: the second signal ends it
      },
      ::testing::ExitedWithCode(128 + SIGINT), "a second interrupt: stopped at once");
  EXPECT_EXIT(
      {
        const InterruptFlag interrupt;
        std::raise(SIGTERM);
        waitPastTheFirst();
        std::raise(SIGINT);
        ::_exit(4);
      },
      ::testing::ExitedWithCode(128 + SIGINT), "stopped at once");
}

// A signal that reaches another thread (a pool thread) is recorded there and
// passed on to the owner, whose handler runs again: that is still the first.
TEST_F(InterruptFlagDeath, ASignalPassedOnToTheOwnerThreadIsNotASecondOne) {
  EXPECT_EXIT(
      {
        const InterruptFlag interrupt;
        std::thread pool([] { ::pthread_kill(::pthread_self(), SIGINT); });
        pool.join();
        // The owner's own delivery of the forwarded signal: it may still be
        // pending until the owner returns from a system call.
        ::usleep(10000);
        if (interrupt.signal() != SIGINT) ::_exit(3);
        ::_exit(0);
      },
      ::testing::ExitedWithCode(0), "");
  EXPECT_EXIT(
      {
        const InterruptFlag interrupt;
        std::thread pool([] { ::pthread_kill(::pthread_self(), SIGINT); });
        pool.join();
        waitPastTheFirst();
        std::raise(SIGINT);
        ::_exit(4);
      },
      ::testing::ExitedWithCode(128 + SIGINT), "stopped at once");
}

// coreutils `timeout -s INT` signals the command and then its process
// group, so the command gets the signal twice within milliseconds: that
// was taken as a second interrupt, which stopped it at once and left what
// it was writing. Two in a burst are one; a later one is still the second.
TEST_F(InterruptFlagDeath, TwoSignalsInABurstAreOneInterrupt) {
  EXPECT_EXIT(
      {
        const InterruptFlag interrupt;
        std::raise(SIGINT);
        std::raise(SIGINT);
        if (interrupt.signal() != SIGINT) ::_exit(3);
        ::_exit(0);
      },
      ::testing::ExitedWithCode(0), "");
  EXPECT_EXIT(
      {
        const InterruptFlag interrupt;
        std::raise(SIGINT);
        std::raise(SIGINT);
        waitPastTheFirst();
        std::raise(SIGINT);
        ::_exit(4);
      },
      ::testing::ExitedWithCode(128 + SIGINT), "stopped at once");
}

TEST(InterruptFlag, RestoresThePreviousHandlersWhenItEnds) {
  struct sigaction before {};
  sigaction(SIGINT, nullptr, &before);
  { const InterruptFlag interrupt; }
  struct sigaction after {};
  sigaction(SIGINT, nullptr, &after);
  EXPECT_EQ(before.sa_handler, after.sa_handler);
}

}  // namespace
}  // namespace snell
