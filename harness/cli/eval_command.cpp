#include <fcntl.h>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string_view>

#include "backends/backend.h"
#include "backends/backend_registry.h"
#include "cli/backend_options.h"
#include "cli/commands.h"
#include "cli/eval_setup.h"
#include "cli/option_checks.h"
#include "cli/shell_word.h"
#include "core/errors.h"
#include "core/message.h"
#include "runner/builtin_eval.h"
#include "runner/eval_client.h"
#include "runner/eval_server_protocol.h"
#include "runner/interrupt_flag.h"
#include "runner/stoppable_input.h"
#include "runner/unix_socket.h"

namespace snell::cli {
namespace {

// On a terminal only (never in CI logs): one line on stderr, rewritten
// every second or so once a run has taken two seconds.
class TerminalProgress {
 public:
  TerminalProgress() : on_(isatty(STDERR_FILENO)), start_(Clock::now()) {}
  ~TerminalProgress() {
    if (shown_) printMessage(stderr, "\n");
  }
  TerminalProgress(const TerminalProgress&) = delete;
  TerminalProgress& operator=(const TerminalProgress&) = delete;

  void update(std::size_t lines) {
    const auto now = Clock::now();
    if (!on_ || now - start_ < std::chrono::seconds(2) || now - shownAt_ < std::chrono::seconds(1))
      return;
    const double seconds = std::chrono::duration<double>(now - start_).count();
    printMessage(stderr, "\rsnell eval: {} lines, {:.0f} lines/s ", lines, lines / seconds);
    std::fflush(stderr);
    shown_ = true;
    shownAt_ = now;
  }

 private:
  using Clock = std::chrono::steady_clock;
  bool on_;
  bool shown_ = false;
  Clock::time_point start_, shownAt_;
};

struct EvalCliOptions {
  std::string backend = "oracle";
  std::string rules = "glsl";
  std::string input = "-";
  std::string device;
  std::string glProvider;
  bool server = false;
  std::string socket;
};

// The input must be lines that can be read: a folder, or a closed
// standard input, would read as no lines, and the exit code would vouch
// for lines nobody checked. (A standard input closed before snell started
// whose number a library reused before main cannot be told from an open
// one; a closed one a client's socket would take is caught.)
void requireReadableInput(const std::string& input) {
  if (input != "-") {
    std::error_code error;
    if (std::filesystem::is_directory(input, error))
      throw UsageError(fmt::format("{}: is a folder; give a JSON Lines file or -", input));
    return;
  }
  struct stat info {};
  if (::fstat(STDIN_FILENO, &info) != 0)
    throw UsageError(
        "standard input is closed: give a JSON Lines file, or send the lines to snell eval's "
        "standard input");
  if (S_ISDIR(info.st_mode))
    throw UsageError("standard input is a folder: give a JSON Lines file, or -");
}

[[noreturn]] void cannotOpen(const std::string& input) {
  throw UsageError(fmt::format("{}: cannot read this file ({}); give a JSON Lines file or -", input,
                               std::strerror(errno)));
}

// A read that failed part way (an I/O error) ends the input early as its
// end does: the answers cover the lines before it.
void requireInputReadToItsEnd(const EvalSummary& summary, const std::string& input) {
  if (summary.readError != 0)
    throw SetupError(fmt::format("{}: reading failed after {} line(s) were answered: {}",
                                 input == "-" ? "standard input" : input, summary.answered,
                                 std::strerror(summary.readError)));
}

// The answers must all have reached standard output (a full disk, a
// closed pipe): otherwise the exit code would vouch for answers nobody has.
void requireAnswersWritten() {
  std::cout.flush();
  if (!std::cout)
    throw SetupError("cannot write the answers to standard output (disk full or pipe closed?)");
}

// Ctrl-C or SIGTERM: the answers written are those of the first lines,
// each whole; the message says where the rest begins. 128 + the signal, as
// a shell reports a process the signal ended.
int reportInterruption(const EvalSummary& summary, const std::string& input, int signal) {
  const std::string rest =
      input == "-" ? fmt::format("input line {}", summary.linesDone + 1)
                   : fmt::format("`tail -n +{} {}`", summary.linesDone + 1, shellWord(input));
  const std::string written =
      summary.linesDone == 0
          ? "no line was answered"
          : fmt::format("the answers written are those of input lines 1 to {}, each whole",
                        summary.linesDone);
  printMessage(stderr, "snell eval: interrupted by {}: {}; the rest begins at {}\n",
               signalName(signal), written, rest);
  return 128 + signal;
}

// The exit code and, for malformed lines, the message on stderr.
int reportSummary(const EvalSummary& summary, const std::string& input) {
  if (summary.malformed) {
    const std::string where = input == "-" ? "standard input" : input;
    printMessage(stderr, "snell eval: {}:{}: {}\n", input == "-" ? "<stdin>" : where,
                 summary.firstMalformedLine, summary.firstMalformedReason);
    printMessage(stderr, "snell eval: {} malformed line(s) in {}; see their \"error\" answers\n",
                 summary.malformed, where);
    return 2;
  }
  return summary.outsideSpec ? 1 : 0;
}

// --server: the same answers from a `snell serve` of this backend.
int askServer(const EvalCliOptions& options) {
  if (options.backend == "oracle")
    throw UsageError("--server asks a driver's server: give --backend (the oracle needs none)");
  if (!options.device.empty() || !options.glProvider.empty())
    throw UsageError(
        "with --server the driver is the server's: give --device or --gl-provider "
        "to `snell serve`");
  requireReadableInput(options.input);
  UniqueFd file;
  if (options.input != "-") {
    file = UniqueFd(::open(options.input.c_str(), O_RDONLY | O_CLOEXEC));
    if (!file) cannotOpen(options.input);
  }
  const std::string socket =
      options.socket.empty() ? defaultServeSocket(options.backend) : options.socket;
  const EvalSummary summary = evaluateOnServer(
      socket, options.backend, options.input == "-" ? STDIN_FILENO : file.get(), std::cout);
  requireAnswersWritten();
  requireInputReadToItsEnd(summary, options.input);
  return reportSummary(summary, options.input);
}

}  // namespace

Command addEvalCommand(CLI::App& app) {
  CLI::App* eval = app.add_subcommand(
      "eval",
      "Evaluate reflect/refract calls given as JSON Lines, on the oracle or a driver, and "
      "physics functions (Fresnel, dispersion, critical and Brewster angles) on the physics "
      "reference");
  auto options = std::make_shared<EvalCliOptions>();
  eval->add_option("--backend", options->backend,
                   "oracle (the default), or a backend (`snell devices`)")
      ->check([](const std::string& value) -> std::string {
        if (value == "oracle" || unknownBackendReason(value).empty()) return "";
        return fmt::format(
            "unknown backend '{}': use oracle or one of {} (`snell devices` describes them)", value,
            fmt::join(backendRegistry().names(), ", "));
      });
  eval->add_option("--rules", options->rules,
                   "Precision rules of the oracle's intervals: glsl (OpenGL) or vulkan; a driver "
                   "is judged by its own API's")
      ->check(CLI::IsMember({"glsl", "vulkan"}));
  addDriverOptions(*eval, options->device, options->glProvider);
  eval->add_flag("--server", options->server,
                 "Ask the `snell serve --backend BACKEND` of this user instead of starting the "
                 "driver here");
  eval->add_option("--socket", options->socket,
                   "With --server: the server's socket, when it was started with --socket")
      ->check(nonEmptyPath());
  eval->add_option("input", options->input, "JSON Lines file, or - for standard input");
  eval->footer(
      R"(Each line: {"fn":"refract","I":[x,y,z],"N":[x,y,z],"eta":0.66} or {"fn":"reflect",...},
vectors of 1 to 4 components; "nan", "inf" and "-inf" are accepted as the vectors' and eta's
numbers. Each answer:
value, lo and hi (the fp32 interval the spec allows), the rules followed, "undefined" per
component where the spec leaves it open, and "alternatives" (value, lo, hi for each way) where
a branch may go either way: a vector is within the spec when it fits one alternative whole.
On gl and vk also exact, within_spec and slack.
Physics lines, answered in double by the physics reference (--backend oracle only):
{"fn":"fresnel","model":"exact"|"schlick"|"schlick_dense_side","cos_i":0.8,"n1":1,"n2":1.5},
{"fn":"ior","glass":"N-BK7"|"water","lambda_nm":589.3}, {"fn":"critical_angle","n1":1.5,"n2":1}
and {"fn":"brewster_angle","n1":1,"n2":1.5} (angles in degrees); each answer's "value".
Input is read, drawn and answered 65536 lines at a time (SNELL_EVAL_CHUNK) on every core
(SNELL_EVAL_THREADS); the answers do not depend on either. On vk the compiled probe programs
are kept where runs keep oracle results: $SNELL_ORACLE_CACHE (off keeps none), else
$XDG_CACHE_HOME/snell/oracle, else ~/.cache/snell/oracle.
Exit 0: every answer within the spec; 1: a driver's vector outside it; 2: a malformed line (the
others are still answered), or input, options or a driver that cannot be used.)");
  return [options, eval] {
    // Standard input read through C stdio, one character per call, was the
    // largest cost after start-up in a profile of a million lines; this
    // command writes only through iostreams (stdout) and fmt (stderr).
    std::ios::sync_with_stdio(false);
    if (!options->socket.empty() && !options->server)
      throw UsageError("--socket names a server's socket: give it with --server");
    if (options->backend != "oracle" && eval->count("--rules")) {
      const std::string own =
          backendRegistry().find(options->backend).family == "vk" ? "vulkan" : "glsl";
      if (options->rules != own)
        throw UsageError(fmt::format(
            "--rules {}: a {} driver is judged by its own API's rules ({}); drop --rules, or "
            "use --backend oracle --rules {}",
            options->rules, options->backend, own, options->rules));
    }
    // With standard output closed the next file opened takes its number: a
    // server's socket then received the client's own answers, and the two
    // waited on each other.
    if (::fcntl(STDOUT_FILENO, F_GETFD) == -1)
      throw UsageError(
          "standard output is closed: the answers would have nowhere to go; give eval a "
          "file or a pipe to write to");
    if (options->server) return askServer(*options);
    // Options that would be passed over without a word are refused (a
    // server refuses both: its driver is already up).
    requireDriverOptionsRead({options->backend}, options->device, options->glProvider);
    requireReadableInput(options->input);
    UniqueFd file;
    if (options->input != "-") {
      file = UniqueFd(::open(options->input.c_str(), O_RDONLY | O_CLOEXEC));
      if (file.get() < 0) cannotOpen(options->input);
    }
    std::unique_ptr<Backend> backend;
    PrecisionRules rules =
        options->rules == "vulkan" ? PrecisionRules::Vulkan : PrecisionRules::Glsl;
    if (options->backend != "oracle") {
      backend = makeEvalBackend(options->backend, options->device, options->glProvider);
      rules = precisionRulesForApi(backend->driverInfo().api);
    }
    EvalOptions evalOptions = evalOptionsFromEnvironment();
    // Ctrl-C ends the input between chunks, or a read waiting on a quiet
    // pipe; the answers written stay whole lines (reportInterruption).
    const InterruptFlag interrupt;
    evalOptions.stop = interrupt.flag();
    StoppableInputBuffer input(options->input == "-" ? STDIN_FILENO : file.get(), interrupt.flag());
    std::istream in(&input);
    EvalSummary summary;
    {
      TerminalProgress progress;
      evalOptions.progress = [&progress](std::size_t lines) { progress.update(lines); };
      summary = evaluateLines(in, std::cout, backend.get(), rules, evalOptions);
    }
    if (input.error() != 0) summary.readError = input.error();
    requireAnswersWritten();
    if (summary.stopped) return reportInterruption(summary, options->input, interrupt.signal());
    requireInputReadToItsEnd(summary, options->input);
    return reportSummary(summary, options->input);
  };
}

}  // namespace snell::cli
