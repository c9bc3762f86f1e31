#pragma once
// Alternatives: where the spec lets an implementation take either way of a
// branch (an Interval condition whose allowed values agree on neither
// outcome, as in refract()'s k < 0 near the critical angle), each way is a
// separate alternative, not merged into one box. A listing's main() is run
// once per combination of such choices (a path); each path gives a
// consistent value for every output, so a read-back vector passes only when
// all its components fit one path, never a mix of two (dEQP's `cond`
// merges them into a box; snell keeps them apart).
//
// glsl::branch consults the explorer that is active on this thread: with
// none, an Unknown condition takes the hull of both ways, as before. Past
// kMaxBranchPaths paths a sample falls back to the hull: stated, not silent
// (explorePaths reports it).
#include <cstddef>
#include <vector>

namespace snell {

inline constexpr std::size_t kMaxBranchPaths = 16;

class BranchPaths {
 public:
  // The outcome at a branch whose condition is Unknown: `then` (true) or
  // `otherwise` (false) for this path, or nullopt-like `hull` when the path
  // count is exceeded (the caller takes the hull of both ways).
  enum class Choice { Then, Otherwise, Hull };
  Choice chooseUnknown();
  // Every branch outcome of the run, decided or chosen, in order: a double
  // evaluation replays them to get the exact value along the same path.
  void record(bool tookThen) { trace_.push_back(tookThen); }

  // Runs `body` once per path (at least once). Returns false when the paths
  // exceeded kMaxBranchPaths: `body` then ran once more with every unknown
  // branch merged to its hull, and only that last run counts. A template,
  // not a std::function: `snell eval` explores once a call, and a lambda
  // holding a few references made a std::function allocate every time.
  template <class Body>
  bool explore(Body&& body) {
    prefix_.clear();
    hullMode_ = false;
    merged_ = false;
    for (std::size_t paths = 1;; ++paths) {
      if (paths > kMaxBranchPaths) {
        startRun(true);
        body();
        hullMode_ = false;
        merged_ = true;
        return false;
      }
      startRun(false);
      body();
      if (!next()) return true;
    }
  }

  // The outcomes of the run that just ended (for BranchReplay).
  const std::vector<bool>& trace() const { return trace_; }
  // Whether the last explore() exceeded kMaxBranchPaths.
  bool mergedToHull() const { return merged_; }

 private:
  bool next();
  void startRun(bool hull) {
    hullMode_ = hull;
    taken_.clear();
    trace_.clear();
  }

  std::vector<bool> prefix_;  // forced choices at unknown branches, in order
  std::vector<bool> taken_;   // choices made at unknown branches in this run
  std::vector<bool> trace_;   // every outcome in this run
  bool hullMode_ = false;
  bool merged_ = false;
};

// Replays recorded outcomes into glsl::branch(bool, ...) calls, so that a
// double evaluation follows a path an Interval evaluation took.
class BranchReplay {
 public:
  explicit BranchReplay(const std::vector<bool>& outcomes) : outcomes_(outcomes) {}
  bool next();

 private:
  const std::vector<bool>& outcomes_;
  std::size_t next_ = 0;
};

// While one is alive, glsl::branch(bool, ...) calls on this thread append
// their outcomes to `outcomes`: a double evaluation's own path, which
// needs no replay along an Interval path with the same outcomes.
class RecordBranches {
 public:
  explicit RecordBranches(std::vector<bool>& outcomes);
  ~RecordBranches();
  RecordBranches(const RecordBranches&) = delete;
  RecordBranches& operator=(const RecordBranches&) = delete;
  void record(bool outcome) { outcomes_.push_back(outcome); }

 private:
  std::vector<bool>& outcomes_;
  RecordBranches* previous_;
};

// The explorer / replay / recorder active on this thread (nullptr: none).
BranchPaths* activeBranchPaths();
BranchReplay* activeBranchReplay();
RecordBranches* activeBranchRecord();

class UseBranchPaths {
 public:
  explicit UseBranchPaths(BranchPaths* paths);
  ~UseBranchPaths();
  UseBranchPaths(const UseBranchPaths&) = delete;
  UseBranchPaths& operator=(const UseBranchPaths&) = delete;

 private:
  BranchPaths* previous_;
};

class UseBranchReplay {
 public:
  explicit UseBranchReplay(BranchReplay* replay);
  ~UseBranchReplay();
  UseBranchReplay(const UseBranchReplay&) = delete;
  UseBranchReplay& operator=(const UseBranchReplay&) = delete;

 private:
  BranchReplay* previous_;
};

}  // namespace snell
