#include "runner/block_pool.h"

#include <algorithm>
#include <utility>

namespace snell {

BlockPool::BlockPool(unsigned threads) {
  for (unsigned k = 1; k < threads; ++k) workers_.emplace_back([this] { workerLoop(); });
}

BlockPool::~BlockPool() {
  {
    const std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  for (std::thread& worker : workers_) worker.join();
}

void BlockPool::keepFirstError(std::exception_ptr error) {
  const std::lock_guard lock(mutex_);
  if (!error_) error_ = error;
}

void BlockPool::takeBlocks() {
  for (;;) {
    const std::size_t begin = next_.fetch_add(block_);
    if (begin >= count_) return;
    try {
      (*work_)(begin, std::min(count_, begin + block_));
    } catch (...) {
      keepFirstError(std::current_exception());
    }
  }
}

void BlockPool::workerLoop() {
  std::size_t seen = 0;
  for (;;) {
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [&] { return stopping_ || generation_ != seen; });
      if (stopping_) return;
      seen = generation_;
    }
    takeBlocks();
    {
      const std::lock_guard lock(mutex_);
      --busy_;
    }
    done_.notify_one();
  }
}

void BlockPool::run(std::size_t count, std::size_t block, const Work& work,
                    const std::function<void()>& callerFirst) {
  {
    const std::lock_guard lock(mutex_);
    work_ = &work;
    count_ = count;
    block_ = std::max<std::size_t>(block, 1);
    next_ = 0;
    error_ = nullptr;
    busy_ = static_cast<unsigned>(workers_.size());
    ++generation_;
  }
  wake_.notify_all();
  if (callerFirst) {
    try {
      callerFirst();
    } catch (...) {
      keepFirstError(std::current_exception());
    }
  }
  takeBlocks();
  std::unique_lock lock(mutex_);
  done_.wait(lock, [&] { return busy_ == 0; });
  work_ = nullptr;
  if (error_) std::rethrow_exception(std::exchange(error_, nullptr));
}

unsigned defaultEvalThreads() { return std::max(1u, std::thread::hardware_concurrency()); }

}  // namespace snell
