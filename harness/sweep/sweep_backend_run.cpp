#include "sweep/sweep_backend_run.h"

#include <fmt/format.h>
#include <poll.h>
#include <signal.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>

#include "oracle/builtin_probe.h"
#include "runner/interrupt_flag.h"
#include "runner/json_fields.h"
#include "runner/worker_process.h"

namespace snell::sweep {
namespace {

using nlohmann::json;

// eval writes non-finite numbers as "nan", "inf", "-inf".
double number(const json& x) {
  if (x.is_number()) return x.get<double>();
  const std::string text = x.get<std::string>();
  if (text == "inf") return std::numeric_limits<double>::infinity();
  if (text == "-inf") return -std::numeric_limits<double>::infinity();
  return std::numeric_limits<double>::quiet_NaN();
}

std::vector<double> numbers(const json& array) {
  std::vector<double> out;
  for (const json& x : array) out.push_back(number(x));
  return out;
}

json jsonNumber(float x) {
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  return static_cast<double>(x);  // exact: a double holds every float, and dumps round-trip
}

json jsonVector(const std::vector<float>& v) {
  json out = json::array();
  for (float x : v) out.push_back(jsonNumber(x));
  return out;
}

}  // namespace

BackendSweep sweepOracle(const std::vector<SweepPoint>& points) {
  BackendSweep sweep;
  sweep.backend = "oracle";
  sweep.renderer = "CPU interval oracle (GLSL 4.60 rules)";
  for (const SweepPoint& point : points) {
    const BuiltinResult result = evaluateBuiltin(point.call, PrecisionRules::Glsl);
    Observation o;
    o.answered = true;
    o.value.assign(result.strict.begin(), result.strict.end());
    o.exact = result.value;
    o.lo = result.lo;
    o.hi = result.hi;
    o.withinSpec = result.allows(result.strict);
    for (bool open : result.undefined) o.undefined = o.undefined || open;
    o.slack = o.withinSpec ? 0 : std::numeric_limits<double>::infinity();
    sweep.points.push_back(std::move(o));
  }
  return sweep;
}

std::string evalInput(const std::vector<SweepPoint>& points) {
  std::string text;
  for (const SweepPoint& point : points) {
    json line = {
        {"fn", point.call.fn}, {"I", jsonVector(point.call.I)}, {"N", jsonVector(point.call.N)}};
    if (point.call.fn == "refract") line["eta"] = jsonNumber(point.call.eta);
    text += jsonText(line) + '\n';
  }
  return text;
}

Observation observationFromAnswer(const std::string& text) {
  const json answer = json::parse(text);
  Observation o;
  if (answer.contains("error")) {
    o.problem = answer.at("error").get<std::string>();
    return o;
  }
  o.answered = true;
  o.value = numbers(answer.at("value"));
  o.exact = numbers(answer.at("exact"));
  o.lo = numbers(answer.at("lo"));
  o.hi = numbers(answer.at("hi"));
  o.withinSpec = answer.at("within_spec").get<bool>();
  o.slack = number(answer.at("slack"));
  if (answer.contains("undefined"))
    for (const json& open : answer.at("undefined")) o.undefined = o.undefined || open.get<bool>();
  return o;
}

namespace {

// One `snell eval` child on `inputFile`: an observation per line, in order;
// those it did not answer carry how the child ended. `hung` is set when it
// was cut off at the time limit.
std::vector<Observation> runEvalChild(const std::string& executable, const std::string& backend,
                                      const std::vector<std::string>& driverArgs,
                                      const std::filesystem::path& inputFile,
                                      std::size_t pointCount, double timeoutSeconds, bool& hung) {
  std::vector<Observation> observations(pointCount);
  std::vector<std::string> argv = {executable, "eval", "--backend", backend};
  argv.insert(argv.end(), driverArgs.begin(), driverArgs.end());
  argv.push_back(inputFile.string());
  WorkerProcess child(argv);
  const auto deadline = std::chrono::steady_clock::now() +
                        std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                            std::chrono::duration<double>(timeoutSeconds));
  std::size_t answered = 0;
  while (!child.stdoutClosed() && !interruptReceived()) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) break;
    std::vector<pollfd> fds = {{child.stdoutFd(), POLLIN, 0}};
    if (child.stderrFd() >= 0) fds.push_back({child.stderrFd(), POLLIN, 0});
    // A signal reaches this thread or another: the wait is short enough
    // to see it soon either way.
    poll(fds.data(), fds.size(), static_cast<int>(std::min<long>(left.count() + 1, 200)));
    if (fds.size() > 1 && (fds[1].revents & (POLLIN | POLLHUP | POLLERR))) child.drainStderr();
    if (!(fds[0].revents & (POLLIN | POLLHUP | POLLERR))) continue;
    for (const std::string& line : child.readLines()) {
      if (answered >= pointCount) break;
      try {
        observations[answered] = observationFromAnswer(line);
      } catch (const json::exception& error) {
        observations[answered].problem = fmt::format("unreadable answer: {}", error.what());
      }
      ++answered;
    }
  }
  const bool stopped = interruptReceived() != 0;
  hung = !stopped && !child.stdoutClosed();
  const std::string how = child.finish(hung || stopped);
  const std::string problem =
      stopped ? std::string("interrupted")
      : hung  ? fmt::format("no answer within {:.3g} s (--timeout)", timeoutSeconds)
              : fmt::format("snell eval --backend {} ended ({}) before answering: {}", backend, how,
                            child.stderrTail(3));
  for (std::size_t k = answered; k < pointCount; ++k) {
    observations[k].problem = problem;
    observations[k].timedOut = hung;
  }
  return observations;
}

struct DriverRun {
  const std::string& executable;
  const std::string& backend;
  const std::vector<std::string>& driverArgs;
  const std::vector<SweepPoint>& points;
  const std::filesystem::path& workDir;
  double timeoutSeconds;
  int childrenLeft;
  BackendSweep& sweep;

  // Runs `subset` in one child; points a crash left unanswered are run
  // again in halves, so a crash lands on the point that causes it.
  void run(const std::vector<std::size_t>& subset) {
    if (interruptReceived()) return;
    std::vector<SweepPoint> chosen;
    for (std::size_t k : subset) chosen.push_back(points[k]);
    const std::filesystem::path input =
        workDir / fmt::format("{}{}-{}.jsonl", kBatchPrefix, childrenLeft, subset.size());
    std::ofstream(input) << evalInput(chosen);
    --childrenLeft;
    bool hung = false;
    const std::vector<Observation> got =
        runEvalChild(executable, backend, driverArgs, input, subset.size(), timeoutSeconds, hung);
    std::filesystem::remove(input);
    std::vector<std::size_t> unanswered;
    for (std::size_t k = 0; k < subset.size(); ++k) {
      sweep.points[subset[k]] = got[k];
      if (!got[k].answered) unanswered.push_back(subset[k]);
    }
    if (unanswered.empty()) return;
    // A hang costs the whole time limit again: not narrowed down.
    const bool narrow = !hung && unanswered.size() > 1 && childrenLeft >= 2;
    if (!narrow) {
      for (std::size_t k : unanswered)
        sweep.points[k].problem +=
            unanswered.size() == 1 ? " (this point alone)"
                                   : fmt::format(" (in a batch of {} points)", unanswered.size());
      return;
    }
    const auto middle = unanswered.begin() + static_cast<std::ptrdiff_t>(unanswered.size() / 2);
    run({unanswered.begin(), middle});
    run({middle, unanswered.end()});
  }
};

}  // namespace

BackendSweep sweepDriver(const std::string& executable, const std::string& backend,
                         const std::vector<SweepPoint>& points,
                         const std::filesystem::path& workDir, double timeoutSeconds,
                         int maxChildren, const std::vector<std::string>& driverArgs) {
  signal(SIGPIPE, SIG_IGN);
  BackendSweep sweep;
  sweep.backend = backend;
  sweep.points.resize(points.size());
  std::vector<std::size_t> all(points.size());
  for (std::size_t k = 0; k < all.size(); ++k) all[k] = k;
  DriverRun{executable, backend, driverArgs, points, workDir, timeoutSeconds, maxChildren, sweep}
      .run(all);
  return sweep;
}

}  // namespace snell::sweep
