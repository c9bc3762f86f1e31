#pragma once
// Where a case's time goes, by phase. The clock is exclusive: entering a
// phase pauses the one it is nested in (the oracle called from inside a
// backend scope is charged to the oracle alone), so the phases of one case
// add up to its wall time, and the summary's columns add up to the run's.
#include <array>
#include <chrono>
#include <cstddef>
#include <string_view>

namespace snell {

enum class Phase : std::size_t {
  Start,     // a worker process from its spawn until its driver is up
  Compile,   // compile, link and pipeline creation (cached programs cost ~0)
  Draw,      // uploads, the draw, and waiting for it to finish
  ReadBack,  // copying the results out of the API
  Oracle,    // the CPU oracle: spec intervals and reference images
  Compare,   // read-backs held against intervals, images against images
  Images,    // image files read and written (goldens, outputs, heat maps)
  Other,     // the rest: bindings, bookkeeping
};
inline constexpr std::size_t kPhaseCount = static_cast<std::size_t>(Phase::Other) + 1;
inline constexpr std::array<Phase, kPhaseCount> kAllPhases{
    Phase::Start,  Phase::Compile, Phase::Draw,   Phase::ReadBack,
    Phase::Oracle, Phase::Compare, Phase::Images, Phase::Other};

// "start", "compile", "draw", "read_back", ...: the results file's keys.
std::string_view phaseName(Phase phase);

struct PhaseTimes {
  std::array<double, kPhaseCount> seconds{};
  double& operator[](Phase p) { return seconds[static_cast<std::size_t>(p)]; }
  double operator[](Phase p) const { return seconds[static_cast<std::size_t>(p)]; }
  double total() const;
  PhaseTimes& operator+=(const PhaseTimes& other);
};

// Records the calling thread's time by phase from construction until
// finish(); time outside every PhaseScope is Other. Recordings nest: an
// inner one stops charging the outer until it finishes.
namespace detail {
struct PhaseClockState {
  bool recording = false;
  int depth = 0;  // recordings nested on this thread
  Phase current = Phase::Other;
  std::chrono::steady_clock::time_point since{};
  PhaseTimes times;
  // Charges the time since the last switch to the current phase.
  void charge();
};
// The clock the recordings read: steady_clock, or a test's own, so that
// the accounting can be tested without sleeping. nullptr: steady_clock.
using PhaseClockNow = std::chrono::steady_clock::time_point (*)();
void setPhaseClock(PhaseClockNow now);
}  // namespace detail

class PhaseRecording {
 public:
  PhaseRecording();
  ~PhaseRecording();
  PhaseRecording(const PhaseRecording&) = delete;
  PhaseRecording& operator=(const PhaseRecording&) = delete;
  PhaseTimes finish();

 private:
  bool finished_ = false;
  detail::PhaseClockState outer_;  // the recording this one interrupts, if any
};

// Charges the calling thread's time to `phase` while it lives; does nothing
// where no recording is running on this thread.
class PhaseScope {
 public:
  explicit PhaseScope(Phase phase);
  ~PhaseScope();
  PhaseScope(const PhaseScope&) = delete;
  PhaseScope& operator=(const PhaseScope&) = delete;

 private:
  bool active_ = false;
  int depth_ = 0;  // the recording it charges: one finished before the scope ends is left alone
  Phase outer_ = Phase::Other;
};

}  // namespace snell
