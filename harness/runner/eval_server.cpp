#include "runner/eval_server.h"

#include <fmt/format.h>
#include <poll.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/time.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <ext/stdio_filebuf.h>
#include <istream>
#include <ostream>
#include <sstream>

#include "core/errors.h"
#include "runner/eval_server_protocol.h"
#include "runner/interrupt_flag.h"

namespace snell {
namespace {

using Clock = std::chrono::steady_clock;

// The header line, read a byte at a time so that nothing of the input
// after it is taken from the socket. A client gets this long to send it.
constexpr std::size_t kMaxHeader = 4096;
constexpr int kHeaderSeconds = 10;

std::string readHeaderLine(int fd) {
  timeval limit{kHeaderSeconds, 0};
  setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &limit, sizeof(limit));
  std::string line;
  char c = 0;
  while (line.size() < kMaxHeader) {
    const ssize_t n = ::recv(fd, &c, 1, 0);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    if (c == '\n') {
      timeval none{0, 0};
      setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &none, sizeof(none));
      return line;
    }
    line.push_back(c);
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

EvalServer::EvalServer(Backend& backend, std::string backendName, ServeOptions options)
    : backend_(backend),
      backendName_(std::move(backendName)),
      options_(std::move(options)),
      rules_(precisionRulesForApi(backend.driverInfo().api)),
      build_(evalBuildId()) {
  std::istringstream in(warmUpLines());
  std::ostringstream answers;
  const EvalSummary warmUp = evaluateLines(in, answers, &backend_, rules_, options_.eval);
  if (warmUp.answered != 8 || warmUp.malformed != 0)
    throw SetupError(fmt::format("the {} probe programs did not answer at start: {}", backendName_,
                                 answers.str()));
  listening_ = listenAt(options_.socketPath);
  socketInode_ = inodeOf(options_.socketPath);
  // After the warm-up: it may load more of the driver's code.
  watched_ = WatchedFiles::ofThisProcess(options_.watch);
}

EvalServer::~EvalServer() {
  // Another server may have taken the path since (after this one was
  // thought gone): remove only the socket this one bound.
  if (socketInode_ != 0 && inodeOf(options_.socketPath) == socketInode_)
    ::unlink(options_.socketPath.c_str());
}

std::string EvalServer::run(std::FILE* log) {
  const InterruptFlag interrupt;
  // A client that leaves mid-answer must end its request, not the server.
  std::signal(SIGPIPE, SIG_IGN);
  Clock::time_point lastRequest = Clock::now();
  for (;;) {
    if (interrupt.signal()) return fmt::format("stopped by signal {}", interrupt.signal());
    pollfd waiting{listening_.get(), POLLIN, 0};
    const int ready = ::poll(&waiting, 1, 1000);
    if (ready < 0 && errno != EINTR)
      throw SetupError(fmt::format("waiting for requests failed: {}", std::strerror(errno)));
    if (ready <= 0) {
      if (options_.idleExit.count() > 0 && Clock::now() - lastRequest >= options_.idleExit)
        return fmt::format("no request for {} s", options_.idleExit.count());
      continue;
    }
    UniqueFd connection(::accept4(listening_.get(), nullptr, nullptr, SOCK_CLOEXEC));
    if (!connection) continue;  // the client gave up before it was taken
    std::string why;
    const bool goOn = answer(connection.get(), log, why);
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
    fmt::print(log, "snell serve: refused a request: {}\n", reply.error);
    std::fflush(log);
  };
  EvalRequest request;
  try {
    request = parseRequestHeader(readHeaderLine(fd));
  } catch (const UsageError& error) {
    refuse(error.what());
    return true;
  }
  if (request.backend != backendName_) {
    refuse(
        fmt::format("this server (pid {}) runs {}, not {}; give --backend {}, or start "
                    "`snell serve --backend {}`",
                    getpid(), backendName_, request.backend, backendName_, request.backend));
    return true;
  }
  if (request.build != build_) {
    refuse(
        fmt::format("this server (pid {}) runs another build of snell than the one asking; "
                    "stop it (kill {}) and start the server of this build",
                    getpid(), getpid()));
    return true;
  }
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
  // The rest of the connection is the input, then room for the answers.
  __gnu_cxx::stdio_filebuf<char> inBuffer(::dup(fd), std::ios::in, 1 << 16);
  __gnu_cxx::stdio_filebuf<char> outBuffer(::dup(fd), std::ios::out, 1 << 16);
  std::istream in(&inBuffer);
  std::ostream out(&outBuffer);
  try {
    reply.summary = evaluateLines(in, out, &backend_, rules_, options_.eval);
  } catch (const UsageError& error) {
    reply.error = error.what();
  } catch (const SetupError& error) {
    reply.error = error.what();
  }
  out.flush();
  const std::string trailer = replyTrailerLine(reply);
  const bool delivered = out.good() && writeAll(fd, trailer.c_str(), trailer.size());
  const double seconds = std::chrono::duration<double>(Clock::now() - started).count();
  if (!reply.error.empty())
    fmt::print(log, "snell serve: a request failed after {:.3f} s: {}\n", seconds, reply.error);
  else
    fmt::print(
        log, "snell serve: {} line{} answered ({} outside the spec, {} malformed) in {:.3f} s{}\n",
        reply.summary.answered, reply.summary.answered == 1 ? "" : "s", reply.summary.outsideSpec,
        reply.summary.malformed, seconds, delivered ? "" : "; the client left before the end");
  std::fflush(log);
  return true;
}

}  // namespace snell
