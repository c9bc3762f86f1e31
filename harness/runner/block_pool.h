#pragma once
// A few threads that share out the blocks of one chunk of `snell eval`
// work: the calling thread takes blocks too, so a pool of N threads keeps N
// cores busy with N - 1 extra threads. Which thread runs a block never
// changes what the block computes, so results stay in input order and the
// same as a serial run.
#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace snell {

class BlockPool {
 public:
  // `threads` counts the caller: 1 runs everything on the caller.
  explicit BlockPool(unsigned threads);
  ~BlockPool();
  BlockPool(const BlockPool&) = delete;
  BlockPool& operator=(const BlockPool&) = delete;

  unsigned threads() const { return static_cast<unsigned>(workers_.size()) + 1; }

  // Calls work(begin, end) for [0, count) cut into blocks of `block`, each
  // block once, on every thread of the pool. The caller runs `callerFirst`
  // (if any) before it takes blocks: work that must stay on the calling
  // thread (a driver's draw) overlaps the others' blocks. Returns when
  // every block is done; the first exception thrown (by callerFirst or a
  // block) is rethrown then, after the other threads have stopped using
  // what `work` refers to.
  using Work = std::function<void(std::size_t begin, std::size_t end)>;
  void run(std::size_t count, std::size_t block, const Work& work,
           const std::function<void()>& callerFirst = {});

 private:
  void workerLoop();
  void takeBlocks();
  void keepFirstError(std::exception_ptr error);

  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable wake_, done_;
  std::size_t generation_ = 0;  // bumped for each run()
  unsigned busy_ = 0;           // workers still in the current run
  bool stopping_ = false;
  const Work* work_ = nullptr;
  std::size_t count_ = 0, block_ = 1;
  std::atomic<std::size_t> next_{0};
  std::exception_ptr error_;
};

// The number of threads `snell eval` uses when not told: every core.
unsigned defaultEvalThreads();

}  // namespace snell
