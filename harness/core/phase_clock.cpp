#include "core/phase_clock.h"

namespace snell {
namespace {

thread_local detail::PhaseClockState tClock;
detail::PhaseClockNow gNow = nullptr;

std::chrono::steady_clock::time_point now() {
  return gNow ? gNow() : std::chrono::steady_clock::now();
}

}  // namespace

std::string_view phaseName(Phase phase) {
  switch (phase) {
    case Phase::Start:
      return "start";
    case Phase::Compile:
      return "compile";
    case Phase::Draw:
      return "draw";
    case Phase::ReadBack:
      return "read_back";
    case Phase::Oracle:
      return "oracle";
    case Phase::Compare:
      return "compare";
    case Phase::Images:
      return "images";
    case Phase::Other:
      return "other";
  }
  return "other";
}

double PhaseTimes::total() const {
  double sum = 0;
  for (double s : seconds) sum += s;
  return sum;
}

PhaseTimes& PhaseTimes::operator+=(const PhaseTimes& other) {
  for (std::size_t k = 0; k < kPhaseCount; ++k) seconds[k] += other.seconds[k];
  return *this;
}

namespace detail {
void PhaseClockState::charge() {
  const auto t = now();
  times[current] += std::chrono::duration<double>(t - since).count();
  since = t;
}

void setPhaseClock(PhaseClockNow clock) { gNow = clock; }
}  // namespace detail

PhaseRecording::PhaseRecording() : outer_(tClock) {
  if (outer_.recording) outer_.charge();
  tClock = detail::PhaseClockState{true, outer_.depth + 1, Phase::Other, now(), {}};
}

PhaseRecording::~PhaseRecording() { finish(); }

PhaseTimes PhaseRecording::finish() {
  if (finished_) return {};
  finished_ = true;
  tClock.charge();
  const PhaseTimes times = tClock.times;
  tClock = outer_;
  // The outer recording resumes now: the inner one's time is not its.
  tClock.since = now();
  return times;
}

PhaseScope::PhaseScope(Phase phase)
    : active_(tClock.recording), depth_(tClock.depth), outer_(tClock.current) {
  if (!active_) return;
  tClock.charge();
  tClock.current = phase;
}

PhaseScope::~PhaseScope() {
  if (!active_ || tClock.depth != depth_) return;
  tClock.charge();
  tClock.current = outer_;
}

}  // namespace snell
