#include "runner/backend_probe.h"

#include <fmt/format.h>
#include <poll.h>
#include <signal.h>

#include <chrono>
#include <memory>
#include <nlohmann/json.hpp>

#include "runner/worker_process.h"

namespace snell {

namespace {

DriverInfo driverFromJson(const nlohmann::json& d) {
  return {d.at("api").get<std::string>(), d.at("api_version").get<std::string>(),
          d.at("renderer").get<std::string>(), d.at("driver_version").get<std::string>(),
          d.at("device_type").get<std::string>()};
}

// The worker's own message ("snell: set-up error: ...") without the prefix.
std::string lastMessage(const std::string& stderrTail) {
  std::string text = stderrTail;
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  for (const char* prefix : {"snell: set-up error: ", "snell: "}) {
    const auto at = text.rfind(prefix);
    if (at != std::string::npos) return text.substr(at + std::string(prefix).size());
  }
  return text;
}

}  // namespace

std::vector<BackendProbe> probeBackends(const std::string& executable,
                                        const std::vector<std::string>& backends,
                                        const std::vector<std::string>& workerArgs,
                                        double timeoutSeconds) {
  signal(SIGPIPE, SIG_IGN);
  std::vector<BackendProbe> probes(backends.size());
  std::vector<std::unique_ptr<WorkerProcess>> workers;
  std::vector<std::string> output(backends.size());
  for (std::size_t k = 0; k < backends.size(); ++k) {
    probes[k].backend = backends[k];
    std::vector<std::string> argv = {executable,  "worker", "--describe", "--backend", backends[k],
                                     "--shaders", ".",      "--out",      ".",         "--golden",
                                     ""};
    argv.insert(argv.end(), workerArgs.begin(), workerArgs.end());
    workers.push_back(std::make_unique<WorkerProcess>(argv));
  }
  const auto deadline = std::chrono::steady_clock::now() +
                        std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                            std::chrono::duration<double>(timeoutSeconds));
  for (;;) {
    std::vector<pollfd> fds;
    std::vector<std::size_t> owners;
    for (std::size_t k = 0; k < workers.size(); ++k) {
      if (workers[k]->stdoutFd() >= 0)
        fds.push_back({workers[k]->stdoutFd(), POLLIN, 0}), owners.push_back(k);
      if (workers[k]->stderrFd() >= 0)
        fds.push_back({workers[k]->stderrFd(), POLLIN, 0}), owners.push_back(k);
    }
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    if (fds.empty() || left.count() <= 0) break;
    poll(fds.data(), fds.size(), static_cast<int>(left.count()) + 1);
    for (std::size_t f = 0; f < fds.size(); ++f) {
      if (!(fds[f].revents & (POLLIN | POLLHUP | POLLERR))) continue;
      WorkerProcess& worker = *workers[owners[f]];
      if (fds[f].fd == worker.stderrFd()) {
        worker.drainStderr();
      } else {
        for (const std::string& line : worker.readLines()) output[owners[f]] += line;
      }
    }
  }
  for (std::size_t k = 0; k < workers.size(); ++k) {
    const bool finished = workers[k]->stdoutFd() < 0;
    const std::string how = workers[k]->finish(!finished);
    BackendProbe& probe = probes[k];
    if (!finished) {
      probe.problem = fmt::format("no answer within {:.0f} s", timeoutSeconds);
      continue;
    }
    try {
      if (how == "exit 0" && !output[k].empty()) {
        probe.driver = driverFromJson(nlohmann::json::parse(output[k]));
        probe.up = true;
        continue;
      }
    } catch (const nlohmann::json::exception&) {
    }
    const std::string message = lastMessage(workers[k]->stderrTail(10));
    probe.problem = message.empty() ? "worker " + how : message;
    if (how.rfind("killed", 0) == 0)
      probe.problem = "worker " + how + (message.empty() ? "" : ": " + message);
  }
  return probes;
}

}  // namespace snell
