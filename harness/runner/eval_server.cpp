#include "runner/eval_server.h"

#include <fmt/format.h>
#include <poll.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <istream>
#include <ostream>
#include <sstream>

#include "core/errors.h"
#include "core/message.h"
#include "runner/eval_server_protocol.h"
#include "runner/interrupt_flag.h"
#include "runner/socket_streams.h"

namespace snell {
namespace {

using Clock = std::chrono::steady_clock;

// The header line: this long at most, sent within this long. Then the
// input: a client may send nothing for this long before its request ends
// (a slow pipe is fine; one left open and forgotten holds no server).
constexpr std::size_t kMaxHeader = 4096;
constexpr std::chrono::seconds kHeaderSeconds{10};
constexpr std::chrono::seconds kInputStallSeconds{60};
// A client that stops reading the answers is let go after this long.
constexpr std::chrono::seconds kAnswerStallSeconds{60};
// Once a request has ended, how long its last answers and trailer may take.
constexpr std::chrono::seconds kFinishSeconds{2};

std::string readHeaderLine(std::istream& in) {
  std::string line;
  for (int c = in.get(); c != std::char_traits<char>::eof(); c = in.get()) {
    if (c == '\n') return line;
    if (line.size() == kMaxHeader) break;
    line.push_back(static_cast<char>(c));
  }
  throw UsageError("no request header arrived (not a snell eval --server client?)");
}

ino_t inodeOf(const std::string& path) {
  struct stat status {};
  return lstat(path.c_str(), &status) == 0 ? status.st_ino : 0;
}

// One call of each probe program `eval` draws (both built-ins, 1 to 4
// components): answered once at start, so that the first request finds
// the programs compiled and the driver's code generator set up (llvmpipe's
// first draw in a process costs 20 to 30 ms beyond any shader cache).
std::string warmUpLines() {
  std::string lines;
  for (int width = 1; width <= 4; ++width) {
    std::string I = "0.6", N = "0";
    for (int k = 1; k < width; ++k) {
      I += k == 1 ? ",-0.8" : ",0";
      N += k == 1 ? ",1" : ",0";
    }
    lines += fmt::format("{{\"fn\":\"reflect\",\"I\":[{}],\"N\":[{}]}}\n", I, N);
    lines += fmt::format("{{\"fn\":\"refract\",\"I\":[{}],\"N\":[{}],\"eta\":0.66}}\n", I, N);
  }
  return lines;
}

}  // namespace

EvalServer::EvalServer(Backend& backend, std::string backendName, ServeOptions options,
                       const InterruptFlag& interrupt)
    : backend_(backend),
      backendName_(std::move(backendName)),
      options_(std::move(options)),
      interrupt_(interrupt),
      rules_(precisionRulesForApi(backend.driverInfo().api)),
      build_(evalBuildId()) {
  std::istringstream in(warmUpLines());
  std::ostringstream answers;
  const EvalSummary warmUp = evaluateLines(in, answers, &backend_, rules_, options_.eval);
  if (warmUp.answered != 8 || warmUp.malformed != 0)
    throw SetupError(fmt::format("the {} probe programs did not answer at start: {}", backendName_,
                                 answers.str()));
  // After the warm-up, which may load more of the driver's code, and
  // before the socket exists: a --watch file that cannot be read stops
  // the server with nothing to clean up.
  watched_ = WatchedFiles::ofThisProcess(options_.watch);
  // Stopped while the driver was starting: no socket, and run() returns
  // at once.
  if (interrupt_.signal()) return;
  listening_ = listenAt(options_.socketPath);
  socketInode_ = inodeOf(options_.socketPath);
}

EvalServer::~EvalServer() {
  // Another server may have taken the path since (after this one was
  // thought gone): remove only the socket this one bound.
  if (socketInode_ != 0 && inodeOf(options_.socketPath) == socketInode_)
    ::unlink(options_.socketPath.c_str());
}

std::string EvalServer::run(std::FILE* log) {
  // A client that leaves mid-answer must end its request, not the server.
  std::signal(SIGPIPE, SIG_IGN);
  Clock::time_point lastRequest = Clock::now();
  for (;;) {
    if (interrupt_.signal()) return fmt::format("stopped by signal {}", interrupt_.signal());
    pollfd waiting{listening_.get(), POLLIN, 0};
    const int ready = ::poll(&waiting, 1, 1000);
    if (ready < 0 && errno != EINTR)
      throw SetupError(fmt::format("waiting for requests failed: {}", std::strerror(errno)));
    if (ready <= 0) {
      if (inodeOf(options_.socketPath) != socketInode_)
        return fmt::format("its socket {} was removed or replaced", options_.socketPath);
      if (options_.idleExit.count() > 0 && Clock::now() - lastRequest >= options_.idleExit)
        return fmt::format("no request for {} s", options_.idleExit.count());
      continue;
    }
    UniqueFd connection(::accept4(listening_.get(), nullptr, nullptr, SOCK_CLOEXEC));
    if (!connection) continue;  // the client gave up before it was taken
    std::string why;
    bool goOn = true;
    try {
      goOn = answer(connection.get(), log, why);
    } catch (const std::exception& error) {
      printMessage(log, "snell serve: a request failed: {}\n", error.what());
      std::fflush(log);
    }
    lastRequest = Clock::now();
    if (!goOn) return why;
  }
}

bool EvalServer::answer(int fd, std::FILE* log, std::string& why) {
  const auto started = Clock::now();
  EvalReply reply;
  const auto refuse = [&](std::string message) {
    reply.error = std::move(message);
    const std::string trailer = replyTrailerLine(reply);
    writeAll(fd, trailer.c_str(), trailer.size());
    printMessage(log, "snell serve: refused a request: {}\n", reply.error);
    std::fflush(log);
  };
  int client = 0;
  if (!peerIsThisUser(fd, &client)) {
    refuse(fmt::format("this server (pid {}) answers only its own user's snell eval", getpid()));
    return true;
  }
  printMessage(log, "snell serve: a request from pid {}\n", client);
  std::fflush(log);
  SocketInput input(fd, interrupt_.flag(), kInputStallSeconds);
  input.setDeadline(Clock::now() + kHeaderSeconds);
  std::istream in(&input);
  EvalRequest request;
  try {
    request = parseRequestHeader(readHeaderLine(in));
  } catch (const UsageError& error) {
    refuse(error.what());
    return true;
  }
  input.setDeadline(std::nullopt);
  if (request.backend != backendName_) {
    refuse(
        fmt::format("this server (pid {}) runs {}, not {}; give --backend {}, or start "
                    "`snell serve --backend {}`",
                    getpid(), backendName_, request.backend, backendName_, request.backend));
    return true;
  }
  // A rebuilt snell asks as another build: the change is what the client
  // is told about, and the server stops, before the builds are compared.
  if (const std::optional<std::string> changed = watched_.firstChanged()) {
    reply.serverStopped = true;
    why = fmt::format("{} changed since the server started", *changed);
    refuse(
        fmt::format("{}: changed since this server (pid {}) started (a rebuilt driver or snell, "
                    "or a --watch file); it has stopped rather than answer with what it "
                    "loaded then: start `snell serve --backend {}` again",
                    *changed, getpid(), backendName_));
    return false;
  }
  if (request.build != build_) {
    refuse(
        fmt::format("this server (pid {}) runs another build of snell than the one asking; "
                    "stop it (kill {}) and start the server of this build",
                    getpid(), getpid()));
    return true;
  }

  // The rest of the connection is the input, then room for the answers.
  SocketOutput output(fd, interrupt_.flag(), kAnswerStallSeconds);
  std::ostream out(&output);
  try {
    reply.summary = evaluateLines(in, out, &backend_, rules_, options_.eval);
  } catch (const std::exception& error) {
    // Whatever one request does, the server stays up for the next.
    reply.error = error.what();
  }
  // What was answered, and why the rest was not, still reach a client
  // that reads them, even after a signal.
  output.finishWithin(kFinishSeconds);
  out.flush();
  const std::string partial = "the answers sent are of the lines it had read, not of all";
  bool stopped = input.end() == SocketEnd::Stopped || output.end() == SocketEnd::Stopped;
  if (reply.error.empty()) {
    if (stopped) {
      reply.error =
          fmt::format("this server (pid {}) was stopped (signal {}) during the request: {}",
                      getpid(), interrupt_.signal(), partial);
    } else if (input.end() == SocketEnd::Stalled) {
      reply.error =
          fmt::format("the input sent nothing for {} s and the server ended the request: {}",
                      kInputStallSeconds.count(), partial);
    } else if (input.end() == SocketEnd::Failed) {
      reply.error = fmt::format("reading the request failed: {}", partial);
    }
  }
  reply.serverStopped = stopped;
  if (output.end() == SocketEnd::NotYet) {
    const std::string trailer = replyTrailerLine(reply);
    out.write(trailer.data(), static_cast<std::streamsize>(trailer.size()));
    out.flush();
  }
  stopped = stopped || output.end() == SocketEnd::Stopped;
  const double seconds = std::chrono::duration<double>(Clock::now() - started).count();
  // A write stopped by the signal leaves no room for the reply's last line:
  // the client sees the connection close, and the log says why.
  const char* lost = output.end() == SocketEnd::NotYet ? ""
                     : output.end() == SocketEnd::Stalled
                         ? "; the client read nothing for a while and was let go before the end"
                     : output.end() == SocketEnd::Stopped
                         ? "; the answers stopped at the signal, while the client was still reading"
                         : "; the client left before the end";
  if (!reply.error.empty())
    printMessage(log, "snell serve: a request failed after {:.3f} s: {}{}\n", seconds, reply.error,
                 lost);
  else
    printMessage(
        log, "snell serve: {} line{} answered ({} outside the spec, {} malformed) in {:.3f} s{}\n",
        reply.summary.answered, reply.summary.answered == 1 ? "" : "s", reply.summary.outsideSpec,
        reply.summary.malformed, seconds, lost);
  std::fflush(log);
  if (stopped) why = fmt::format("stopped by signal {}", interrupt_.signal());
  return !stopped;
}

}  // namespace snell
