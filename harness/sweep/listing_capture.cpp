#include "sweep/listing_capture.h"

#include <fmt/format.h>
#include <poll.h>
#include <signal.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <limits>
#include <nlohmann/json.hpp>

#include "core/errors.h"
#include "core/scene.h"
#include "runner/interrupt_flag.h"
#include "runner/json_fields.h"
#include "runner/worker_process.h"

namespace snell::sweep {
namespace {

using nlohmann::json;

json jsonNumber(float x) {
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  return static_cast<double>(x);
}

float number(const json& x) {
  if (x.is_number()) return x.get<float>();
  const std::string text = x.get<std::string>();
  if (text == "inf") return std::numeric_limits<float>::infinity();
  if (text == "-inf") return -std::numeric_limits<float>::infinity();
  return std::numeric_limits<float>::quiet_NaN();
}

std::vector<DrawSpec> readJob(const std::filesystem::path& jobFile) {
  std::ifstream in(jobFile);
  if (!in) throw UsageError(fmt::format("{}: cannot read the sweep's job file", jobFile.string()));
  std::vector<DrawSpec> draws;
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) draws.push_back(parseDrawLine(line));
  return draws;
}

}  // namespace

std::string drawCaptureLine(std::size_t draw, const DrawCapture& capture) {
  json line = {{"draw", draw}, {"compiled", capture.compiled}};
  if (!capture.problem.empty()) line["error"] = capture.problem;
  if (!capture.log.empty()) line["log"] = capture.log;
  json varyings = json::array();
  for (const CapturedVarying& v : capture.varyings) {
    json data = json::array();
    for (float x : v.data) data.push_back(jsonNumber(x));
    varyings.push_back({{"name", v.name}, {"components", v.components}, {"data", data}});
  }
  line["varyings"] = varyings;
  return jsonText(line);
}

DrawCapture drawCaptureFromLine(const std::string& text) {
  const json line = json::parse(text);
  DrawCapture capture;
  capture.answered = true;
  capture.compiled = line.at("compiled").get<bool>();
  if (line.contains("error")) capture.problem = line.at("error").get<std::string>();
  if (line.contains("log")) capture.log = line.at("log").get<std::string>();
  for (const json& v : line.at("varyings")) {
    CapturedVarying varying;
    varying.name = v.at("name").get<std::string>();
    varying.components = v.at("components").get<int>();
    for (const json& x : v.at("data")) varying.data.push_back(number(x));
    capture.varyings.push_back(std::move(varying));
  }
  return capture;
}

int runListingWorker(const std::filesystem::path& jobFile, std::size_t start,
                     const std::string& backendName, const BackendOptions& options) {
  const std::vector<DrawSpec> draws = readJob(jobFile);
  const Scene base = makeScene("sweep");
  std::unique_ptr<Backend> backend = makeBackend(backendName, options);
  for (std::size_t k = start; k < draws.size(); ++k) {
    DrawCapture capture;
    try {
      const PreparedDraw draw = prepareDraw(draws[k], base);
      const CaptureJob job{draw.program, draw.bindings.uniforms, draw.bindings.attributes,
                           draw.manifest.captureVertex, draw.bindings.vertexCount};
      const CaptureOutcome outcome = backend->captureVertexOutputs(job);
      capture.compiled = outcome.compile.ok;
      capture.log = outcome.compile.log;
      capture.varyings = outcome.varyings;
    } catch (const std::runtime_error& error) {
      capture.problem = error.what();
    }
    std::cout << drawCaptureLine(k, capture) << std::endl;  // flushed: the sweep reads as we go
  }
  return 0;
}

std::vector<DrawCapture> captureDraws(const std::string& executable, const std::string& backend,
                                      const std::vector<std::string>& driverArgs,
                                      const std::filesystem::path& jobFile, std::size_t drawCount,
                                      double timeoutSeconds, int maxChildren) {
  signal(SIGPIPE, SIG_IGN);
  std::vector<DrawCapture> captures(drawCount);
  std::size_t next = 0;
  for (int children = 0; next < drawCount && !interruptReceived(); ++children) {
    if (children == maxChildren) {
      for (std::size_t k = next; k < drawCount; ++k)
        captures[k].problem = fmt::format("not run: {} driver children ended early", children);
      break;
    }
    std::vector<std::string> argv = {executable,         "sweep",
                                     "--listing-worker", jobFile.string(),
                                     "--listing-start",  std::to_string(next),
                                     "--backend",        backend};
    argv.insert(argv.end(), driverArgs.begin(), driverArgs.end());
    WorkerProcess child(argv);
    auto deadline = std::chrono::steady_clock::now() +
                    std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                        std::chrono::duration<double>(timeoutSeconds));
    while (!child.stdoutClosed() && next < drawCount && !interruptReceived()) {
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
          deadline - std::chrono::steady_clock::now());
      if (left.count() <= 0) break;
      std::vector<pollfd> fds = {{child.stdoutFd(), POLLIN, 0}};
      if (child.stderrFd() >= 0) fds.push_back({child.stderrFd(), POLLIN, 0});
      poll(fds.data(), fds.size(), static_cast<int>(std::min<long>(left.count() + 1, 200)));
      if (fds.size() > 1 && (fds[1].revents & (POLLIN | POLLHUP | POLLERR))) child.drainStderr();
      if (!(fds[0].revents & (POLLIN | POLLHUP | POLLERR))) continue;
      for (const std::string& line : child.readLines()) {
        if (next >= drawCount) break;
        try {
          captures[next] = drawCaptureFromLine(line);
        } catch (const nlohmann::json::exception& error) {
          captures[next].answered = false;
          captures[next].problem = fmt::format("unreadable answer: {}", error.what());
        }
        ++next;
        // Each draw has its own time limit.
        deadline = std::chrono::steady_clock::now() +
                   std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                       std::chrono::duration<double>(timeoutSeconds));
      }
    }
    if (next >= drawCount) {
      child.finish(false);
      break;
    }
    if (interruptReceived()) {
      child.finish(true);
      break;
    }
    const bool hung = !child.stdoutClosed();
    const std::string how = child.finish(hung);
    captures[next].answered = false;
    captures[next].timedOut = hung;
    captures[next].problem =
        hung
            ? fmt::format("no answer within {:.3g} s (hang, or --timeout too short)",
                          timeoutSeconds)
            : fmt::format("the driver child ended ({}) on this draw: {}", how, child.stderrTail(3));
    ++next;  // the next child starts after the draw that crashed
  }
  return captures;
}

}  // namespace snell::sweep
