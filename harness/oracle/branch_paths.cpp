#include "oracle/branch_paths.h"

#include <stdexcept>

namespace snell {
namespace {

thread_local BranchPaths* tPaths = nullptr;
thread_local BranchReplay* tReplay = nullptr;
thread_local RecordBranches* tRecord = nullptr;

}  // namespace

BranchPaths::Choice BranchPaths::chooseUnknown() {
  if (hullMode_) return Choice::Hull;
  const bool then = taken_.size() < prefix_.size() ? prefix_[taken_.size()] : true;
  taken_.push_back(then);
  return then ? Choice::Then : Choice::Otherwise;
}

// Depth first: the last unknown branch that took `then` takes `otherwise`
// next, and every choice after it starts over.
bool BranchPaths::next() {
  std::size_t k = taken_.size();
  while (k > 0 && !taken_[k - 1]) --k;
  if (k == 0) return false;
  prefix_.assign(taken_.begin(), taken_.begin() + static_cast<std::ptrdiff_t>(k - 1));
  prefix_.push_back(false);
  return true;
}

bool BranchReplay::next() {
  if (next_ >= outcomes_.size())
    throw std::logic_error("branch replay: the evaluation took more branches than were recorded");
  return outcomes_[next_++];
}

BranchPaths* activeBranchPaths() { return tPaths; }
BranchReplay* activeBranchReplay() { return tReplay; }
RecordBranches* activeBranchRecord() { return tRecord; }

UseBranchPaths::UseBranchPaths(BranchPaths* paths) : previous_(tPaths) { tPaths = paths; }
UseBranchPaths::~UseBranchPaths() { tPaths = previous_; }
UseBranchReplay::UseBranchReplay(BranchReplay* replay) : previous_(tReplay) { tReplay = replay; }
UseBranchReplay::~UseBranchReplay() { tReplay = previous_; }

RecordBranches::RecordBranches(std::vector<bool>& outcomes)
    : outcomes_(outcomes), previous_(tRecord) {
  tRecord = this;
}
RecordBranches::~RecordBranches() { tRecord = previous_; }

}  // namespace snell
