#include "runner/eval_client.h"

#include <fmt/format.h>
#include <poll.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <memory>
#include <optional>
#include <string>
#include <thread>

#include "core/errors.h"
#include "runner/eval_server_protocol.h"
#include "runner/unix_socket.h"

namespace snell {
namespace {

// The server must be this user's own: another user's socket at the same
// path could answer anything.
void requireOwnServer(int fd, const std::string& socketPath) {
  if (!peerIsThisUser(fd))
    throw UsageError(fmt::format(
        "{}: the server here runs as another user; start your own with --socket elsewhere",
        socketPath));
}

// Sends the input, then shuts the sending side so the server sees its end.
// Stops early when the server is gone (it said why in its trailer). A read
// that fails is kept in `readError` (its errno): the input did not end.
void sendInput(int socket, int input, std::atomic<bool>& done, std::atomic<int>& readError) {
  std::array<char, 1 << 16> buffer;
  for (;;) {
    const ssize_t n = ::read(input, buffer.data(), buffer.size());
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) readError = errno;
    if (n <= 0 || !writeAll(socket, buffer.data(), static_cast<std::size_t>(n))) break;
  }
  ::shutdown(socket, SHUT_WR);
  done = true;
}

// Copies the answers out whole: a server stopped part way through one
// leaves no cut-off line in the output.
class WholeLines {
 public:
  explicit WholeLines(std::ostream& out) : out_(out) {}
  void write(const char* begin, const char* end) {
    const char* last = begin;
    for (const char* p = end; p != begin; --p)
      if (p[-1] == '\n') {
        last = p;
        break;
      }
    if (last == begin) {
      partial_.append(begin, end);
      return;
    }
    out_.write(partial_.data(), static_cast<std::streamsize>(partial_.size()));
    out_.write(begin, last - begin);
    // Passed on as they come: a co-process waits for its answers before
    // it sends more.
    out_.flush();
    partial_.assign(last, end);
  }
  // Text held back after the last whole line: at the server's trailer
  // there is none, every answer ending in its newline.
  bool cutOff() const { return !partial_.empty(); }

 private:
  std::ostream& out_;
  std::string partial_;
};

}  // namespace

EvalSummary evaluateOnServer(const std::string& socketPath, const std::string& backend, int input,
                             std::ostream& out, std::chrono::milliseconds silence) {
  UniqueFd connection = connectTo(socketPath);
  if (!connection) {
    const int error = errno;
    struct stat info {};
    if (::stat(socketPath.c_str(), &info) == 0 && !S_ISSOCK(info.st_mode))
      throw UsageError(fmt::format(
          "{}: is a {}, not a socket; give --socket the socket a `snell serve` listens at",
          socketPath, S_ISDIR(info.st_mode) ? "folder" : "file"));
    if (error != ENOENT && error != ECONNREFUSED)
      throw UsageError(
          fmt::format("{}: cannot connect ({}); give --socket the socket of a "
                      "`snell serve` of your own",
                      socketPath, std::strerror(error)));
    throw UsageError(fmt::format(
        "{}: no snell serve answers here ({}); start one with `snell serve --backend {}` (and "
        "the same --socket), or leave out --server",
        socketPath, std::strerror(error), backend));
  }
  requireOwnServer(connection.get(), socketPath);
  const std::string header = requestHeaderLine({backend, evalBuildId()});
  if (!writeAll(connection.get(), header.c_str(), header.size()))
    throw SetupError(fmt::format("{}: the server closed the connection at once", socketPath));

  const int fd = connection.get();
  // The sender owns nothing but its buffer. When the server ended the
  // request early while the input (a pipe) has not ended, it is left
  // blocked in its read: the command is about to exit with the error.
  // It reads a descriptor of its own, so the caller may close `input`.
  const int ownInput = ::dup(input);
  if (ownInput < 0)
    throw SetupError(fmt::format("cannot read the input: {}", std::strerror(errno)));
  auto senderDone = std::make_shared<std::atomic<bool>>(false);
  auto readError = std::make_shared<std::atomic<int>>(0);
  std::thread sender([fd, ownInput, senderDone, readError] {
    sendInput(fd, ownInput, *senderDone, *readError);
    ::close(ownInput);
  });
  // Its socket is then kept open (shut, so its writes fail) rather than
  // closed, so that its number is never reused under it.
  struct EndSender {
    std::thread& sender;
    const std::atomic<bool>& done;
    UniqueFd& connection;
    bool answered = false;  // the server read the whole input: the sender is past its reads
    ~EndSender() {
      ::shutdown(connection.get(), SHUT_RDWR);
      if (answered || done) {
        sender.join();
      } else {
        sender.detach();
        connection.release();
      }
    }
  } endSender{sender, *senderDone, connection};

  std::array<char, 1 << 16> buffer;
  WholeLines answers(out);
  std::optional<std::string> trailer;
  auto heardAt = std::chrono::steady_clock::now();
  for (;;) {
    const auto quiet = std::chrono::duration_cast<std::chrono::milliseconds>(
        std::chrono::steady_clock::now() - heardAt);
    pollfd ready{fd, POLLIN, 0};
    const int polled =
        quiet >= silence ? 0 : ::poll(&ready, 1, static_cast<int>((silence - quiet).count()));
    if (polled < 0 && errno == EINTR) continue;
    if (polled == 0) {
      out.flush();
      throw SetupError(fmt::format(
          "{}: the server sent nothing for {} s: it is stopped (Ctrl-Z in its terminal; `kill "
          "-CONT` it) or stuck; the answers written (whole lines only) cover part of the input",
          socketPath, std::chrono::duration_cast<std::chrono::seconds>(silence).count()));
    }
    const ssize_t n = polled < 0 ? -1 : ::recv(fd, buffer.data(), buffer.size(), 0);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    heardAt = std::chrono::steady_clock::now();
    const char* begin = buffer.data();
    const char* end = begin + n;
    if (trailer) {
      trailer->append(begin, end);
      continue;
    }
    const char* mark = static_cast<const char*>(std::memchr(begin, kEvalTrailerMark, n));
    answers.write(begin, mark ? mark : end);
    if (mark) trailer.emplace(mark + 1, end);
  }
  out.flush();
  if (!out) throw SetupError("cannot write the answers (standard output failed)");
  if (!trailer)
    throw SetupError(fmt::format(
        "{}: the server closed the connection before it finished (see its log); the answers "
        "written (whole lines only) cover part of the input",
        socketPath));
  if (answers.cutOff())
    throw SetupError(fmt::format(
        "{}: the server's answers end part way through a line (a server of another protocol?)",
        socketPath));
  const EvalReply reply = parseReplyTrailer(*trailer);
  if (!reply.error.empty()) throw SetupError(reply.error);
  endSender.answered = true;
  EvalSummary summary = reply.summary;
  summary.readError = *readError;
  return summary;
}

}  // namespace snell
