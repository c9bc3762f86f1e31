#include "core/phase_clock.h"

#include <gtest/gtest.h>

namespace snell {
namespace {

// A clock the test moves by hand: every phase's time is exact.
std::chrono::steady_clock::time_point gFakeNow{};
std::chrono::steady_clock::time_point fakeNow() { return gFakeNow; }
void advance(double seconds) {
  gFakeNow += std::chrono::duration_cast<std::chrono::steady_clock::duration>(
      std::chrono::duration<double>(seconds));
}

class PhaseClockTest : public ::testing::Test {
 protected:
  void SetUp() override { detail::setPhaseClock(fakeNow); }
  void TearDown() override { detail::setPhaseClock(nullptr); }
};

TEST_F(PhaseClockTest, NestedPhasesAreChargedExclusively) {
  PhaseRecording recording;
  advance(1);  // Other
  {
    const PhaseScope draw(Phase::Draw);
    advance(2);
    {
      const PhaseScope oracle(Phase::Oracle);
      advance(4);
    }
    advance(8);  // back in Draw
  }
  advance(16);  // Other again
  const PhaseTimes t = recording.finish();
  EXPECT_DOUBLE_EQ(t[Phase::Draw], 10);
  EXPECT_DOUBLE_EQ(t[Phase::Oracle], 4);
  EXPECT_DOUBLE_EQ(t[Phase::Other], 17);
  EXPECT_DOUBLE_EQ(t[Phase::Compile], 0);
  EXPECT_DOUBLE_EQ(t.total(), 31);  // the wall time, each second counted once
}

TEST_F(PhaseClockTest, ScopesOutsideARecordingChargeNothing) {
  {
    const PhaseScope orphan(Phase::Compile);
    advance(5);
  }
  PhaseRecording recording;
  advance(1);
  const PhaseTimes t = recording.finish();
  EXPECT_DOUBLE_EQ(t[Phase::Compile], 0);
  EXPECT_DOUBLE_EQ(t.total(), 1);
}

TEST_F(PhaseClockTest, AnInnerRecordingPausesTheOuterOne) {
  PhaseRecording outer;
  const PhaseScope images(Phase::Images);
  advance(1);
  PhaseTimes inner;
  {
    PhaseRecording nested;
    const PhaseScope oracle(Phase::Oracle);
    advance(3);
    inner = nested.finish();
  }
  advance(2);
  const PhaseTimes t = outer.finish();
  EXPECT_DOUBLE_EQ(inner[Phase::Oracle], 3);
  EXPECT_DOUBLE_EQ(t[Phase::Images], 3);
  EXPECT_DOUBLE_EQ(t[Phase::Oracle], 0);
}

TEST(PhaseTimes, AddsPhaseByPhaseAndNamesEveryPhase) {
  PhaseTimes a, b;
  a[Phase::Draw] = 1;
  b[Phase::Draw] = 2;
  b[Phase::Start] = 0.5;
  a += b;
  EXPECT_DOUBLE_EQ(a[Phase::Draw], 3);
  EXPECT_DOUBLE_EQ(a[Phase::Start], 0.5);
  EXPECT_DOUBLE_EQ(a.total(), 3.5);
  EXPECT_EQ(phaseName(Phase::ReadBack), "read_back");
  for (Phase p : kAllPhases) EXPECT_FALSE(phaseName(p).empty());
}

}  // namespace
}  // namespace snell
