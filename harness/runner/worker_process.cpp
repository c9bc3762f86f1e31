#include "runner/worker_process.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <string>
#include <system_error>

#include "core/errors.h"

extern char** environ;

namespace snell {
namespace {

constexpr std::size_t kStderrKept = 8192;

void closeFd(int& fd) {
  if (fd >= 0) close(fd);
  fd = -1;
}

// The program to start for argv[0]. snell's own workers are started from
// this process's own image (/proc/self/exe), not from its path: a snell
// rebuilt or replaced while a run goes on would otherwise join the run as
// its later workers. argv[0] keeps the path, for ps and messages.
std::string programFor(const std::string& path) {
  std::error_code error;
  const auto own = std::filesystem::read_symlink("/proc/self/exe", error);
  // Once the file is replaced, the link reads "PATH (deleted)".
  const bool same = !error && (own.string() == path || own.string() == path + " (deleted)");
  return same ? "/proc/self/exe" : path;
}

}  // namespace

WorkerProcess::WorkerProcess(const std::vector<std::string>& argv) {
  int in[2] = {-1, -1}, out[2] = {-1, -1}, err[2] = {-1, -1};
  if (pipe2(in, O_CLOEXEC) || pipe2(out, O_CLOEXEC) || pipe2(err, O_CLOEXEC)) {
    const int error = errno;
    for (int* pair : {in, out, err}) {
      closeFd(pair[0]);
      closeFd(pair[1]);
    }
    throw SetupError(fmt::format("cannot create pipes for a worker: {}", std::strerror(error)));
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, in[0], 0);
  posix_spawn_file_actions_adddup2(&actions, out[1], 1);
  posix_spawn_file_actions_adddup2(&actions, err[1], 2);
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  const std::string program = programFor(argv[0]);
  const int rc = posix_spawn(&pid_, program.c_str(), &actions, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  close(in[0]);
  close(out[1]);
  close(err[1]);
  inFd_ = in[1];
  outFd_ = out[0];
  errFd_ = err[0];
  if (rc != 0) {
    closeFd(inFd_);
    closeFd(outFd_);
    closeFd(errFd_);
    throw SetupError(fmt::format("cannot start worker {}: {}", argv[0], std::strerror(rc)));
  }
  fcntl(outFd_, F_SETFL, O_NONBLOCK);
  fcntl(errFd_, F_SETFL, O_NONBLOCK);
}

WorkerProcess::~WorkerProcess() { finish(true); }

bool WorkerProcess::send(const std::string& line) {
  if (inFd_ < 0) return false;
  const std::string text = line + "\n";
  std::size_t written = 0;
  while (written < text.size()) {
    const ssize_t n = write(inFd_, text.data() + written, text.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;  // EPIPE: the worker is gone (SIGPIPE is ignored)
    written += static_cast<std::size_t>(n);
  }
  return true;
}

std::vector<std::string> WorkerProcess::readLines() {
  char buffer[65536];
  while (outFd_ >= 0) {
    const ssize_t n = read(outFd_, buffer, sizeof buffer);
    if (n > 0) {
      outBuffer_.append(buffer, static_cast<std::size_t>(n));
    } else if (n == 0) {
      closeFd(outFd_);
    } else {
      if (errno != EAGAIN && errno != EINTR) closeFd(outFd_);
      break;
    }
  }
  std::vector<std::string> lines;
  for (std::size_t end; (end = outBuffer_.find('\n')) != std::string::npos;) {
    lines.push_back(outBuffer_.substr(0, end));
    outBuffer_.erase(0, end + 1);
  }
  return lines;
}

void WorkerProcess::drainStderr() {
  char buffer[8192];
  while (errFd_ >= 0) {
    const ssize_t n = read(errFd_, buffer, sizeof buffer);
    if (n > 0) {
      errTail_.append(buffer, static_cast<std::size_t>(n));
      if (errTail_.size() > kStderrKept) errTail_.erase(0, errTail_.size() - kStderrKept);
    } else if (n == 0 || (errno != EAGAIN && errno != EINTR)) {
      closeFd(errFd_);
    } else {
      break;
    }
  }
}

void WorkerProcess::kill() {
  if (pid_ > 0) ::kill(pid_, SIGKILL);
}

std::string WorkerProcess::finish(bool kill) {
  closeFd(inFd_);
  if (pid_ <= 0) return "already reaped";
  if (kill) ::kill(pid_, SIGKILL);
  int status = 0;
  while (waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
  }
  pid_ = -1;
  drainStderr();
  closeFd(outFd_);
  closeFd(errFd_);
  if (WIFSIGNALED(status))
    return fmt::format("killed by signal {} ({})", WTERMSIG(status), strsignal(WTERMSIG(status)));
  return fmt::format("exit {}", WEXITSTATUS(status));
}

std::string WorkerProcess::stderrTail(std::size_t lines) const {
  std::size_t start = errTail_.size();
  std::size_t found = 0;
  while (start > 0 && found <= lines) {
    start = errTail_.rfind('\n', start - 1);
    if (start == std::string::npos) {
      start = 0;
      break;
    }
    ++found;
  }
  std::string tail = errTail_.substr(start);
  while (!tail.empty() && (tail.front() == '\n')) tail.erase(0, 1);
  return tail;
}

}  // namespace snell
