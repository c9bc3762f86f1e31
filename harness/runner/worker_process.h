#pragma once
// One `snell worker` child process and the pipes to it.
#include <sys/types.h>

#include <optional>
#include <string>
#include <vector>

namespace snell {

class WorkerProcess {
 public:
  WorkerProcess(const std::vector<std::string>& argv);
  ~WorkerProcess();
  WorkerProcess(const WorkerProcess&) = delete;
  WorkerProcess& operator=(const WorkerProcess&) = delete;

  // False when the worker's stdin is closed (it died).
  bool send(const std::string& line);
  // Reads what is available; returns complete lines from stdout.
  std::vector<std::string> readLines();
  void drainStderr();
  bool stdoutClosed() const { return outFd_ < 0; }
  int stdoutFd() const { return outFd_; }
  int stderrFd() const { return errFd_; }
  pid_t pid() const { return pid_; }
  // Sends SIGKILL without waiting, so several hung workers die at once.
  void kill();
  // Kills (SIGKILL) if still running and reaps; returns a description of
  // how it ended: "killed by signal 11 (Segmentation fault)", "exit 2".
  std::string finish(bool kill);
  std::string stderrTail(std::size_t lines) const;

 private:
  pid_t pid_ = -1;
  int inFd_ = -1, outFd_ = -1, errFd_ = -1;
  std::string outBuffer_;
  std::string errTail_;
};

}  // namespace snell
