#include "runner/supervisor.h"

#include <fmt/format.h>
#include <poll.h>
#include <signal.h>

#include <algorithm>
#include <chrono>
#include <deque>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

#include "core/atomic_file.h"
#include "runner/case_result_json.h"
#include "runner/worker_process.h"

namespace snell {
namespace {

using Clock = std::chrono::steady_clock;

struct Slot {
  std::unique_ptr<WorkerProcess> worker;
  std::string backend;              // the backend its worker has loaded
  std::optional<std::size_t> task;  // the case it is running
  Clock::time_point started, deadline;
};

CaseResult lostCase(const Task& task, Status status, const std::string& message, double seconds) {
  CaseResult r;
  r.caseId = task.caseId;
  r.backend = task.backend;
  r.status = status;
  r.message = message;
  r.seconds = seconds;
  return r;
}

class Supervision {
 public:
  Supervision(const std::vector<Task>& tasks, const SupervisorOptions& options,
              const ResultCallback& onResult)
      : tasks_(tasks),
        options_(options),
        onResult_(onResult),
        results_(tasks.size()),
        finished_(tasks.size(), false),
        slots_(static_cast<std::size_t>(std::max(1, options.jobs))) {
    for (std::size_t k = 0; k < tasks.size(); ++k) pending_.push_back(k);
  }

  // 0 for the first backend the tasks name, 1 for the next, ...
  std::size_t backendOrder(const std::string& backend) const {
    std::vector<std::string> seen;
    for (const Task& t : tasks_) {
      if (t.backend == backend) return seen.size();
      if (std::find(seen.begin(), seen.end(), t.backend) == seen.end()) seen.push_back(t.backend);
    }
    return 0;
  }

  std::vector<CaseResult> run() {
    while (done_ < tasks_.size() && !stopped()) {
      for (Slot& slot : slots_)
        if (!slot.task && !pending_.empty()) assign(slot);
      wait();
    }
    for (Slot& slot : slots_) slot.worker.reset();
    if (done_ < tasks_.size()) {
      std::vector<CaseResult> finished;
      for (std::size_t k = 0; k < results_.size(); ++k)
        if (finished_[k]) finished.push_back(std::move(results_[k]));
      return finished;
    }
    return std::move(results_);
  }

 private:
  bool stopped() const { return options_.stop && *options_.stop; }

  // Each worker start loads a driver (and, for images, the image module),
  // so a slot keeps to the backend its worker loaded while that backend has
  // cases left. A slot that needs a worker takes the backend the fewest
  // other slots run: with as many slots as backends, one worker per
  // backend. Every other backend (by first appearance) takes its cases
  // from the end, so that two backends' workers reach the same case, and
  // the lock on its shared reference image, only once, where they meet.
  void assign(Slot& slot) {
    const auto ofBackend = [&](const std::string& backend) {
      return [this, backend](std::size_t k) { return tasks_[k].backend == backend; };
    };
    std::string backend = slot.worker ? slot.backend : "";
    if (backend.empty() ||
        std::none_of(pending_.begin(), pending_.end(), ofBackend(slot.backend))) {
      std::size_t fewest = slots_.size() + 1;
      for (std::size_t k : pending_) {
        const std::string& candidate = tasks_[k].backend;
        const auto running = static_cast<std::size_t>(
            std::count_if(slots_.begin(), slots_.end(), [&](const Slot& other) {
              return &other != &slot && other.worker && other.backend == candidate;
            }));
        if (running < fewest) {
          fewest = running;
          backend = candidate;
        }
      }
    }
    const bool fromEnd = backendOrder(backend) % 2 == 1;
    const auto it =
        fromEnd
            ? std::prev(std::find_if(pending_.rbegin(), pending_.rend(), ofBackend(backend)).base())
            : std::find_if(pending_.begin(), pending_.end(), ofBackend(backend));
    const std::size_t index = *it;
    pending_.erase(it);
    const Task& task = tasks_[index];
    if (slot.worker && slot.backend != task.backend) slot.worker.reset();
    if (!slot.worker) {
      std::vector<std::string> argv = {options_.executable, "worker",    "--backend",
                                       task.backend,        "--shaders", options_.shaders};
      if (options_.validation) argv.push_back("--validation");
      argv.insert(argv.end(), {"--out", options_.outDir, "--golden", options_.goldenDir});
      argv.insert(argv.end(), options_.backendArgs.begin(), options_.backendArgs.end());
      if (!options_.blessFlags.empty())
        argv.insert(argv.end(), {"--bless-flags", options_.blessFlags});
      if (!options_.runId.empty()) argv.insert(argv.end(), {"--run-id", options_.runId});
      if (!options_.oracleStore.empty())
        argv.insert(argv.end(), {"--oracle-store", options_.oracleStore});
      argv.insert(
          argv.end(),
          {"--spawned-at", std::to_string(std::chrono::duration_cast<std::chrono::nanoseconds>(
                                              std::chrono::steady_clock::now().time_since_epoch())
                                              .count())});
      slot.worker = std::make_unique<WorkerProcess>(argv);
      slot.backend = task.backend;
    }
    slot.task = index;
    slot.started = Clock::now();
    slot.deadline = slot.started + std::chrono::duration_cast<Clock::duration>(
                                       std::chrono::duration<double>(task.timeoutSeconds));
    if (!slot.worker->send(task.caseId)) workerDied(slot);
  }

  void finishTask(Slot& slot, CaseResult result) {
    const std::size_t index = *slot.task;
    slot.task.reset();
    results_[index] = std::move(result);
    finished_[index] = true;
    ++done_;
    if (onResult_) onResult_(index, results_[index]);
  }

  double elapsed(const Slot& slot) const {
    return std::chrono::duration<double>(Clock::now() - slot.started).count();
  }

  // A worker killed or dead in the middle of a case may have been writing
  // one of its files: the temporary it wrote first is removed, so that it
  // does not stay among the case's images.
  // `pid` is read before the worker is reaped, which forgets it.
  void removeWhatItWasWriting(const Slot& slot, pid_t pid) const {
    if (slot.task && !options_.outDir.empty())
      removeTemporaryFilesOf(pid,
                             std::filesystem::path(options_.outDir) / tasks_[*slot.task].caseId);
  }

  void workerDied(Slot& slot) {
    const pid_t pid = slot.worker->pid();
    const std::string how = slot.worker->finish(false);
    const std::string tail = slot.worker->stderrTail(10);
    removeWhatItWasWriting(slot, pid);
    slot.worker.reset();
    if (!slot.task) return;
    finishTask(slot,
               lostCase(tasks_[*slot.task], Status::Crash,
                        fmt::format("worker {}{}{}", how, tail.empty() ? "" : "; stderr:\n", tail),
                        elapsed(slot)));
  }

  void timedOut(Slot& slot, double seconds) {
    const pid_t pid = slot.worker->pid();
    slot.worker->finish(true);
    const std::string tail = slot.worker->stderrTail(10);
    removeWhatItWasWriting(slot, pid);
    slot.worker.reset();
    finishTask(slot, lostCase(tasks_[*slot.task], Status::Timeout,
                              fmt::format("no result after {:.1f} s (limit {:.1f} s); worker "
                                          "killed{}{}",
                                          seconds, tasks_[*slot.task].timeoutSeconds,
                                          tail.empty() ? "" : "; stderr:\n", tail),
                              seconds));
  }

  void readResults(Slot& slot) {
    for (const std::string& line : slot.worker->readLines()) {
      if (!slot.task) continue;
      CaseResult result;
      try {
        result = caseResultFromJson(nlohmann::json::parse(line));
      } catch (const nlohmann::json::exception& error) {
        result = lostCase(tasks_[*slot.task], Status::Crash,
                          fmt::format("worker sent a malformed result ({}): {}", error.what(),
                                      line.substr(0, 200)),
                          elapsed(slot));
      }
      finishTask(slot, std::move(result));
    }
    if (slot.worker->stdoutClosed()) workerDied(slot);
  }

  void wait() {
    std::vector<pollfd> fds;
    std::vector<Slot*> owners;
    Clock::time_point nearest = Clock::time_point::max();
    for (Slot& slot : slots_) {
      if (!slot.worker) continue;
      if (slot.worker->stdoutFd() >= 0) {
        fds.push_back({slot.worker->stdoutFd(), POLLIN, 0});
        owners.push_back(&slot);
      }
      if (slot.worker->stderrFd() >= 0) {
        fds.push_back({slot.worker->stderrFd(), POLLIN, 0});
        owners.push_back(&slot);
      }
      if (slot.task) nearest = std::min(nearest, slot.deadline);
    }
    int timeoutMs = -1;
    if (nearest != Clock::time_point::max())
      timeoutMs = static_cast<int>(std::max<long>(
          0, std::chrono::duration_cast<std::chrono::milliseconds>(nearest - Clock::now()).count() +
                 1));
    if (!fds.empty()) poll(fds.data(), fds.size(), timeoutMs);
    // A signal interrupts poll(); a worker it also killed is not a Crash.
    if (stopped()) return;
    for (std::size_t k = 0; k < fds.size(); ++k) {
      Slot& slot = *owners[k];
      if (!slot.worker || !(fds[k].revents & (POLLIN | POLLHUP | POLLERR))) continue;
      if (fds[k].fd == slot.worker->stderrFd())
        slot.worker->drainStderr();
      else
        readResults(slot);
    }
    // Every expired worker is signalled before any is reaped: reaping one
    // that is tearing down JIT threads takes a while, and must not make the
    // next one overrun its own limit.
    const Clock::time_point now = Clock::now();
    std::vector<std::pair<Slot*, double>> expired;
    for (Slot& slot : slots_)
      if (slot.task && slot.worker && now >= slot.deadline) {
        expired.emplace_back(&slot, elapsed(slot));
        slot.worker->kill();
      }
    for (auto& [slot, seconds] : expired) timedOut(*slot, seconds);
  }

  const std::vector<Task>& tasks_;
  const SupervisorOptions& options_;
  const ResultCallback& onResult_;
  std::vector<CaseResult> results_;
  std::vector<bool> finished_;
  std::vector<Slot> slots_;
  std::deque<std::size_t> pending_;
  std::size_t done_ = 0;
};

}  // namespace

std::vector<CaseResult> superviseTasks(const std::vector<Task>& tasks,
                                       const SupervisorOptions& options,
                                       const ResultCallback& onResult) {
  // A worker that dies while we write to it must not kill the supervisor.
  signal(SIGPIPE, SIG_IGN);
  return Supervision(tasks, options, onResult).run();
}

}  // namespace snell
