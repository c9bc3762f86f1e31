// `snell serve` and `snell eval --server` as a user runs them: the same
// answers and exit codes as `snell eval` with the driver in its own
// process, one clear exit-2 message for each way a request cannot be
// answered, and a server that stops when a watched file changes.
#include <fcntl.h>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "snell_process.h"

namespace {

namespace fs = std::filesystem;
using snell::testing::Outcome;
using snell::testing::readText;
using snell::testing::runSnell;

// A folder of its own for each test: sockets, logs and inputs.
struct Scratch {
  fs::path dir;
  explicit Scratch(const std::string& name)
      : dir(fs::temp_directory_path() / fmt::format("snell-serve-{}-{}", name, ::getpid())) {
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  ~Scratch() { fs::remove_all(dir); }
  fs::path file(const std::string& name, const std::string& text) const {
    std::ofstream(dir / name) << text;
    return dir / name;
  }
};

// `snell serve ARGS` in the background, its stderr in `log`.
class Server {
 public:
  Server(const std::vector<std::string>& args, const fs::path& log) {
    std::vector<std::string> all = {"serve"};
    all.insert(all.end(), args.begin(), args.end());
    pid_ = snell::testing::spawnSnell(all, log.string());
  }
  ~Server() {
    if (pid_ > 0) {
      ::kill(pid_, SIGKILL);
      ::waitpid(pid_, nullptr, 0);
    }
  }
  // The exit code once it has exited within `limit`, else nothing.
  std::optional<int> exitWithin(std::chrono::seconds limit) {
    const auto end = std::chrono::steady_clock::now() + limit;
    while (std::chrono::steady_clock::now() < end) {
      int status = 0;
      if (::waitpid(pid_, &status, WNOHANG) == pid_) {
        pid_ = -1;
        return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    return std::nullopt;
  }
  pid_t pid() const { return pid_; }

 private:
  pid_t pid_ = -1;
};

// Waits until the log says the server listens (driver start takes a while
// on a loaded machine): its first line, "snell serve: BACKEND (...) on
// SOCKET, watching N files; pid P".
bool listening(const fs::path& log) {
  for (int k = 0; k < 600; ++k) {
    const std::string text = readText(log);
    if (text.rfind("snell serve: ", 0) == 0 && text.find("; pid ") != std::string::npos)
      return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  return false;
}

// Waits until the log holds `text`.
bool logged(const fs::path& log, const std::string& text) {
  for (int k = 0; k < 600; ++k) {
    if (readText(log).find(text) != std::string::npos) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return false;
}

// A Unix socket of this process at `path`: listening, or connected to it.
int unixSocket(const fs::path& path, bool listen) {
  const int fd = ::socket(AF_UNIX, SOCK_STREAM, 0);
  sockaddr_un address{};
  address.sun_family = AF_UNIX;
  std::strncpy(address.sun_path, path.c_str(), sizeof(address.sun_path) - 1);
  const auto* where = reinterpret_cast<const sockaddr*>(&address);
  const int ok = listen ? ::bind(fd, where, sizeof(address)) | ::listen(fd, 1)
                        : ::connect(fd, where, sizeof(address));
  if (ok != 0) {
    ::close(fd);
    return -1;
  }
  return fd;
}

// Everything the peer sends until it closes, or `limit` passes.
std::string readUntilClosed(int fd, std::chrono::seconds limit) {
  timeval timeout{static_cast<time_t>(limit.count()), 0};
  ::setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &timeout, sizeof(timeout));
  std::string text;
  char buffer[4096];
  for (ssize_t n; (n = ::recv(fd, buffer, sizeof(buffer), 0)) > 0;) text.append(buffer, n);
  return text;
}

const char* kLines =
    "{\"fn\":\"refract\",\"I\":[0.6,-0.8,0],\"N\":[0,1,0],\"eta\":0.66}\n"
    "{\"fn\":\"reflect\",\"I\":[0.6,-0.8],\"N\":[0,1]}\n"
    "{\"fn\":\"refract\",\"I\":[0.9,-0.1,0.42],\"N\":[0,1,0],\"eta\":1.5}\n";

TEST(EvalServerCli, AnswersAsTheDriverInItsOwnProcessDoes) {
  const Scratch scratch("same");
  const fs::path socket = scratch.dir / "gl.sock", log = scratch.dir / "serve.log";
  Server server({"--backend", "gl", "--socket", socket.string()}, log);
  ASSERT_TRUE(listening(log)) << readText(log);
  const fs::path good = scratch.file("good.jsonl", kLines);
  const fs::path bad = scratch.file("bad.jsonl", std::string(kLines) + "not json\n");
  for (const fs::path& input : {good, bad}) {
    const Outcome local = runSnell(fmt::format("eval --backend gl {}", input.string()));
    const Outcome served = runSnell(
        fmt::format("eval --backend gl --server --socket {} {}", socket.string(), input.string()));
    EXPECT_EQ(served.code, local.code) << served.out;
    EXPECT_EQ(served.out, local.out);
  }
  EXPECT_EQ(runSnell(fmt::format("eval --backend gl --server --socket {} {}", socket.string(),
                                 good.string()))
                .code,
            0);
  // A read of the input that fails part way is said as eval says it, not
  // taken for its end (reading address 0 of a process is EIO).
  const Outcome failed = runSnell(
      fmt::format("eval --backend gl --server --socket {} /proc/self/mem", socket.string()));
  EXPECT_EQ(failed.code, 2) << failed.out;
  EXPECT_NE(failed.out.find("/proc/self/mem: reading failed after 0 line(s) were answered: "
                            "Input/output error"),
            std::string::npos)
      << failed.out;
  // Standard input too.
  const Outcome piped = runSnell(
      fmt::format("eval --backend gl --server --socket {} - < {}", socket.string(), good.string()));
  EXPECT_EQ(piped.code, 0) << piped.out;
  EXPECT_EQ(piped.out, runSnell(fmt::format("eval --backend gl {}", good.string())).out);
  EXPECT_NE(readText(log).find("3 lines answered"), std::string::npos) << readText(log);
}

TEST(EvalServerCli, StopsWhenAWatchedFileChanges) {
  const Scratch scratch("watch");
  const fs::path socket = scratch.dir / "gl.sock", log = scratch.dir / "serve.log";
  const fs::path watched = scratch.file("driver.json", "{}\n");
  const fs::path input = scratch.file("in.jsonl", kLines);
  Server server({"--backend", "gl", "--socket", socket.string(), "--watch", watched.string()}, log);
  ASSERT_TRUE(listening(log)) << readText(log);
  const std::string ask =
      fmt::format("eval --backend gl --server --socket {} {}", socket.string(), input.string());
  ASSERT_EQ(runSnell(ask).code, 0);
  std::ofstream(watched) << "{\"rebuilt\":true}\n";
  const Outcome refused = runSnell(ask);
  EXPECT_EQ(refused.code, 2) << refused.out;
  EXPECT_NE(refused.out.find(watched.string() + ": changed since this server"), std::string::npos)
      << refused.out;
  EXPECT_EQ(refused.out.find("\"line\""), std::string::npos) << "no answers from a stale server";
  EXPECT_EQ(server.exitWithin(std::chrono::seconds(20)), std::optional<int>(0)) << readText(log);
  EXPECT_FALSE(fs::exists(socket)) << "a stopped server removes its socket";
}

// A rebuilt snell asks as another build: the server says what changed and
// stops, instead of refusing that build and serving the old one on.
TEST(EvalServerCli, AClientOfARebuiltSnellStopsTheServer) {
  const Scratch scratch("rebuilt");
  const fs::path socket = scratch.dir / "gl.sock", log = scratch.dir / "serve.log";
  const fs::path watched = scratch.file("snell-itself", "old\n");
  Server server({"--backend", "gl", "--socket", socket.string(), "--watch", watched.string()}, log);
  ASSERT_TRUE(listening(log)) << readText(log);
  std::ofstream(watched) << "rebuilt\n";
  const int fd = unixSocket(socket, false);
  ASSERT_GE(fd, 0) << std::strerror(errno);
  const std::string header = "{\"snell_eval\":1,\"backend\":\"gl\",\"build\":\"another\"}\n";
  ASSERT_EQ(::write(fd, header.data(), header.size()), static_cast<ssize_t>(header.size()));
  ::shutdown(fd, SHUT_WR);
  const std::string reply = readUntilClosed(fd, std::chrono::seconds(20));
  ::close(fd);
  EXPECT_NE(reply.find("changed since this server"), std::string::npos) << reply;
  EXPECT_EQ(server.exitWithin(std::chrono::seconds(20)), std::optional<int>(0)) << readText(log);
}

// A server gone part way through an answer: the client writes the answers
// that arrived whole, and none cut off.
// A server gone part way through an answer: the client writes the answers
// that arrived whole, and none cut off. One whose reply ends while a line is
// cut off is refused too, not passed with the piece dropped.
TEST(EvalServerCli, AServerGoneMidAnswerLeavesOnlyWholeLines) {
  const Scratch scratch("cut");
  const fs::path socket = scratch.dir / "gone.sock";
  const fs::path input = scratch.file("in.jsonl", kLines);
  const std::string cut = "{\"line\":1}\n{\"line\":2,\"va";
  const std::string trailer =
      "\x1e{\"answered\":2,\"malformed\":0,\"outside_spec\":0,\"first_malformed_line\":0,"
      "\"first_malformed_reason\":\"\",\"server_stopped\":false}\n";
  for (const auto& [reply, message] : std::vector<std::pair<std::string, std::string>>{
           {cut, "the answers written (whole lines only) cover part of the input"},
           {cut + trailer, "the server's answers end part way through a line"}}) {
    fs::remove(socket);
    const int listener = unixSocket(socket, true);
    ASSERT_GE(listener, 0) << std::strerror(errno);
    std::thread gone([&, reply = reply] {
      const int fd = ::accept(listener, nullptr, nullptr);
      if (fd < 0) return;
      char buffer[4096];
      (void)::recv(fd, buffer, sizeof(buffer), 0);
      (void)::write(fd, reply.data(), reply.size());
      ::close(fd);
    });
    const Outcome o = runSnell(
        fmt::format("eval --backend gl --server --socket {} {}", socket.string(), input.string()));
    gone.join();
    ::close(listener);
    EXPECT_EQ(o.code, 2) << o.out;
    EXPECT_EQ(o.out.rfind("{\"line\":1}\n", 0), 0u) << o.out;
    EXPECT_EQ(o.out.find("{\"line\":2"), std::string::npos) << o.out;
    EXPECT_NE(o.out.find(message), std::string::npos) << o.out;
  }
}

TEST(EvalServerCli, EachUnansweredRequestIsOneExit2Message) {
  const Scratch scratch("refuse");
  const fs::path socket = scratch.dir / "gl.sock", log = scratch.dir / "serve.log";
  const fs::path input = scratch.file("in.jsonl", kLines);
  const auto expectExit2 = [](const std::string& args, const std::string& message) {
    const Outcome o = runSnell(args);
    EXPECT_EQ(o.code, 2) << args << "\n" << o.out;
    EXPECT_NE(o.out.find(message), std::string::npos) << args << "\n" << o.out;
  };
  expectExit2(
      fmt::format("eval --backend gl --server --socket {} {}", socket.string(), input.string()),
      "no snell serve answers here");
  expectExit2(fmt::format("eval --server {}", input.string()), "give --backend");
  expectExit2(fmt::format("eval --backend gl --socket {} {}", socket.string(), input.string()),
              "give it with --server");
  expectExit2(fmt::format("eval --backend gl --server --device 0 {}", input.string()),
              "to `snell serve`");
  const fs::path plain = scratch.file("not-a-socket", "keep me\n");
  expectExit2(fmt::format("serve --backend gl --socket {}", plain.string()), "is not a socket");
  // A client given a file or a folder is told it is none, not "start one".
  expectExit2(
      fmt::format("eval --backend gl --server --socket {} {}", plain.string(), input.string()),
      "is a file, not a socket");
  expectExit2(fmt::format("eval --backend gl --server --socket {} {}", scratch.dir.string(),
                          input.string()),
              "is a folder, not a socket");
  EXPECT_EQ(readText(plain), "keep me\n");
  expectExit2(
      fmt::format("serve --backend gl --socket {}/{}", scratch.dir.string(), std::string(120, 's')),
      "a socket path must have");

  Server server({"--backend", "gl", "--socket", socket.string()}, log);
  ASSERT_TRUE(listening(log)) << readText(log);
  expectExit2(
      fmt::format("eval --backend vk --server --socket {} {}", socket.string(), input.string()),
      "runs gl, not vk");
  expectExit2(fmt::format("serve --backend gl --socket {}", socket.string()),
              "a server already answers here");
  // Still serving after refusing.
  EXPECT_EQ(runSnell(fmt::format("eval --backend gl --server --socket {} {}", socket.string(),
                                 input.string()))
                .code,
            0);
}

TEST(EvalServerCli, StopsWhenIdleAndOnSigterm) {
  const Scratch scratch("stop");
  const fs::path idleSocket = scratch.dir / "idle.sock", idleLog = scratch.dir / "idle.log";
  Server idle({"--backend", "gl", "--socket", idleSocket.string(), "--idle-exit", "1"}, idleLog);
  EXPECT_EQ(idle.exitWithin(std::chrono::seconds(60)), std::optional<int>(0)) << readText(idleLog);
  EXPECT_NE(readText(idleLog).find("stopped: no request for 1 s"), std::string::npos)
      << readText(idleLog);
  EXPECT_FALSE(fs::exists(idleSocket));

  const fs::path socket = scratch.dir / "term.sock", log = scratch.dir / "term.log";
  Server server({"--backend", "gl", "--socket", socket.string()}, log);
  ASSERT_TRUE(listening(log)) << readText(log);
  ::kill(server.pid(), SIGTERM);
  EXPECT_EQ(server.exitWithin(std::chrono::seconds(20)), std::optional<int>(0)) << readText(log);
  EXPECT_FALSE(fs::exists(socket));
}

TEST(EvalServerCli, ALineThatIsNotUtf8IsAnsweredAndTheServerStaysUp) {
  const Scratch scratch("utf8");
  const fs::path socket = scratch.dir / "gl.sock", log = scratch.dir / "serve.log";
  const fs::path input = scratch.file("in.jsonl", std::string(kLines) + "{\"fn\":\"\xff\"}\n");
  const fs::path good = scratch.file("good.jsonl", kLines);
  const Outcome local = runSnell(fmt::format("eval --backend gl {}", input.string()));
  EXPECT_EQ(local.code, 2) << local.out;
  EXPECT_NE(local.out.find(fmt::format("{}:4: ", input.string())), std::string::npos) << local.out;
  EXPECT_EQ(local.out.find("internal error"), std::string::npos) << local.out;
  Server server({"--backend", "gl", "--socket", socket.string()}, log);
  ASSERT_TRUE(listening(log)) << readText(log);
  const Outcome served = runSnell(
      fmt::format("eval --backend gl --server --socket {} {}", socket.string(), input.string()));
  EXPECT_EQ(served.code, 2) << served.out;
  EXPECT_EQ(served.out, local.out);
  EXPECT_EQ(runSnell(fmt::format("eval --backend gl --server --socket {} {}", socket.string(),
                                 good.string()))
                .code,
            0)
      << readText(log);
}

TEST(EvalServerCli, SigtermDuringARequestStopsTheServerAndFailsTheRequest) {
  const Scratch scratch("busy");
  const fs::path socket = scratch.dir / "gl.sock", log = scratch.dir / "serve.log";
  const fs::path input = scratch.file("in.jsonl", kLines);
  Server server({"--backend", "gl", "--socket", socket.string()}, log);
  ASSERT_TRUE(listening(log)) << readText(log);
  // A client whose input stays open for 6 s after its lines.
  Outcome client;
  std::thread asking([&] {
    client = runSnell(fmt::format("eval --backend gl --server --socket {}", socket.string()),
                      fmt::format("(cat {}; sleep 6) |", input.string()));
  });
  ASSERT_TRUE(logged(log, "a request from pid")) << readText(log);
  ::kill(server.pid(), SIGTERM);
  EXPECT_EQ(server.exitWithin(std::chrono::seconds(4)), std::optional<int>(0)) << readText(log);
  asking.join();
  EXPECT_EQ(client.code, 2) << client.out;
  EXPECT_NE(client.out.find("was stopped (signal 15) during the request"), std::string::npos)
      << client.out;
  EXPECT_FALSE(fs::exists(socket));
}

TEST(EvalServerCli, SigtermWhileAClientReadsNoAnswersStopsTheServer) {
  const Scratch scratch("unread");
  const fs::path socket = scratch.dir / "gl.sock", log = scratch.dir / "serve.log";
  std::string many;
  for (int k = 0; k < 7000; ++k) many += kLines;  // answers far past the socket's and pipe's room
  const fs::path input = scratch.file("in.jsonl", many);
  Server server({"--backend", "gl", "--socket", socket.string()}, log);
  ASSERT_TRUE(listening(log)) << readText(log);
  std::thread asking([&] {
    runSnell(fmt::format("eval --backend gl --server --socket {} {} | sleep 6", socket.string(),
                         input.string()));
  });
  ASSERT_TRUE(logged(log, "a request from pid")) << readText(log);
  std::this_thread::sleep_for(std::chrono::seconds(1));  // the answers fill the pipe
  ::kill(server.pid(), SIGTERM);
  EXPECT_EQ(server.exitWithin(std::chrono::seconds(4)), std::optional<int>(0)) << readText(log);
  asking.join();
  // The client was still there: the log blamed it for leaving.
  EXPECT_NE(readText(log).find("the answers stopped at the signal, while the client was still "
                               "reading"),
            std::string::npos)
      << readText(log);
  EXPECT_EQ(readText(log).find("the client left"), std::string::npos) << readText(log);
}

TEST(EvalServerCli, StopsWhenItsSocketIsRemoved) {
  const Scratch scratch("removed");
  const fs::path socket = scratch.dir / "gl.sock", log = scratch.dir / "serve.log";
  Server server({"--backend", "gl", "--socket", socket.string()}, log);
  ASSERT_TRUE(listening(log)) << readText(log);
  fs::remove(socket);
  EXPECT_EQ(server.exitWithin(std::chrono::seconds(20)), std::optional<int>(0)) << readText(log);
  EXPECT_NE(readText(log).find("was removed or replaced"), std::string::npos) << readText(log);
}

// Input that cannot be read as lines is exit 2, never read as no lines.
TEST(EvalServerCli, AnUnreadableInputIsExit2) {
  const Scratch scratch("folder");
  for (const char* flags : {"", "--backend gl --server --socket /nonexistent.sock"}) {
    for (const auto& [input, message] : std::vector<std::pair<std::string, std::string>>{
             {scratch.dir.string(), "is a folder"},
             {"- < " + scratch.dir.string(), "standard input is a folder"},
             // Closed: the first descriptor a client opens (its socket)
             // would otherwise be read as the input.
             {"- <&-", "standard input is closed"}}) {
      const Outcome o = runSnell(fmt::format("eval {} {}", flags, input));
      EXPECT_EQ(o.code, 2) << flags << " " << input << ": " << o.out;
      EXPECT_NE(o.out.find(message), std::string::npos) << flags << " " << input << ": " << o.out;
    }
  }
  // A read that fails part way (reading address 0 of a process is EIO).
  const Outcome failed = runSnell("eval /proc/self/mem");
  EXPECT_EQ(failed.code, 2) << failed.out;
  EXPECT_NE(failed.out.find("/proc/self/mem: reading failed after 0 line(s) were answered: "
                            "Input/output error"),
            std::string::npos)
      << failed.out;
}

TEST(EvalServerCli, AnEmptySocketPathIsExit2) {
  for (const char* args :
       {"eval --backend gl --server --socket '' -", "serve --backend gl --socket ''"}) {
    const Outcome o = runSnell(args);
    EXPECT_EQ(o.code, 2) << args << ": " << o.out;
    EXPECT_NE(o.out.find("--socket: an empty path"), std::string::npos) << args << ": " << o.out;
  }
}

// `snell ARGS` through the shell with stdout and stderr as `redirections`
// say; its exit code.
int exitCode(const std::string& args, const std::string& redirections) {
  const int status = std::system(fmt::format("{} {} {}", SNELL_BINARY, args, redirections).c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// With stdout closed the client's socket took its number: the answers were
// sent back into the client's own request and both sides waited (or it
// died of SIGPIPE without a word). Refused before anything is read.
TEST(EvalServerCli, AClosedStandardOutputIsExit2) {
  const Scratch scratch("closed-stdout");
  const fs::path input = scratch.file("lines.jsonl", kLines);
  const fs::path log = scratch.dir / "log.txt";
  for (const char* flags : {"", "--backend gl --server --socket /nonexistent.sock"}) {
    EXPECT_EQ(exitCode(fmt::format("eval {} {}", flags, input.string()), ">&- 2>" + log.string()),
              2)
        << flags;
    EXPECT_NE(readText(log).find("standard output is closed"), std::string::npos)
        << flags << ": " << readText(log);
  }
}

// A message that cannot be written (stderr on a full disk, a reader that
// has left) is lost, and nothing else: fmt's exception from inside a catch
// block aborted eval (exit 134) and the server, mid-request.
TEST(EvalServerCli, AStderrThatCannotBeWrittenLosesOnlyTheMessages) {
  const Scratch scratch("full-stderr");
  const fs::path bad = scratch.file("bad.jsonl", "{\"fn\":\"x\"}\n");
  EXPECT_EQ(exitCode("eval " + bad.string(), ">/dev/null 2>/dev/full"), 2);
  EXPECT_EQ(exitCode("eval " + bad.string(), ">/dev/null 2>&-"), 2);
  const fs::path socket = scratch.dir / "s.sock";
  Server server({"--backend", "gl", "--socket", socket.string()}, "/dev/full");
  for (int k = 0; k < 600 && !fs::exists(socket); ++k)
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  ASSERT_TRUE(fs::exists(socket)) << "the server did not start";
  const fs::path input = scratch.file("lines.jsonl", kLines);
  for (int request = 0; request < 2; ++request) {
    const Outcome o = runSnell(
        fmt::format("eval --backend gl --server --socket {} {}", socket.string(), input.string()));
    EXPECT_EQ(o.code, 0) << o.out;
    EXPECT_EQ(std::count(o.out.begin(), o.out.end(), '\n'), 3) << o.out;
  }
  EXPECT_FALSE(server.exitWithin(std::chrono::seconds(0)).has_value());
}

}  // namespace
