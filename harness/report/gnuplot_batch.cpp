#include "report/gnuplot_batch.h"

#include <fmt/format.h>
#include <string.h>
#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string_view>

#include "core/errors.h"

namespace snell {

GnuplotBatch::GnuplotBatch(std::filesystem::path workDir)
    : dir_(std::move(workDir)), script_("set encoding utf8\n") {}

std::filesystem::path GnuplotBatch::file(const std::string& stem, const std::string& extension) {
  return dir_ / fmt::format("{}{}{}", stem, files_++, extension);
}

void GnuplotBatch::add(const std::string& commands) {
  // Each `set output 'FILE'` draws to FILE.drawing, renamed in run().
  constexpr std::string_view kOutput = "set output '";
  std::string drawn;
  std::size_t from = 0;
  for (std::size_t at; (at = commands.find(kOutput, from)) != std::string::npos;) {
    const std::size_t begin = at + kOutput.size();
    const std::size_t end = commands.find('\'', begin);
    if (end == std::string::npos) break;
    const std::filesystem::path output = commands.substr(begin, end - begin);
    const std::filesystem::path drawing = output.string() + kDrawing;
    outputs_.emplace_back(drawing, output);
    drawn += commands.substr(from, begin - from) + drawing.string();
    from = end;
  }
  script_ += drawn + commands.substr(from);
  script_ += "\nunset output\nreset\nunset object\n";
}

void GnuplotBatch::run() {
  const std::filesystem::path script = dir_ / kScript;
  const std::filesystem::path log = dir_ / kLog;
  std::ofstream(script) << script_;
  const std::string command =
      fmt::format("cd '{}' && gnuplot {} >{} 2>&1", dir_.string(), kScript, kLog);
  const int status = std::system(command.c_str());
  const auto dropDrawings = [&] {
    std::error_code ignored;
    for (const auto& [drawing, output] : outputs_) std::filesystem::remove(dir_ / drawing, ignored);
  };
  // std::system ignores SIGINT while gnuplot runs: Ctrl-C stops gnuplot alone.
  if (status != -1 && WIFSIGNALED(status)) {
    dropDrawings();
    throw SetupError(fmt::format("gnuplot was stopped by SIG{}: no chart was written",
                                 sigabbrev_np(WTERMSIG(status))));
  }
  if (status != 0) {
    dropDrawings();
    const std::string output = readBytes(log);
    throw SetupError(fmt::format("gnuplot failed ({}): {}; install gnuplot-nox (ci/packages.txt)",
                                 WIFEXITED(status) ? WEXITSTATUS(status) : -1,
                                 output.substr(0, 2000)));
  }
  for (const auto& [drawing, output] : outputs_) {
    std::error_code error;
    std::filesystem::rename(dir_ / drawing, dir_ / output, error);
    if (error)
      throw SetupError(fmt::format("{}: cannot write the chart ({})", (dir_ / output).string(),
                                   error.message()));
  }
}

std::string readBytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

}  // namespace snell
