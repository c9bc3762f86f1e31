#include "report/gnuplot_batch.h"

#include <fmt/format.h>
#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "core/errors.h"

namespace snell {

GnuplotBatch::GnuplotBatch(std::filesystem::path workDir)
    : dir_(std::move(workDir)), script_("set encoding utf8\n") {}

std::filesystem::path GnuplotBatch::file(const std::string& stem, const std::string& extension) {
  return dir_ / fmt::format("{}{}{}", stem, files_++, extension);
}

void GnuplotBatch::add(const std::string& commands) {
  script_ += commands;
  script_ += "\nunset output\nreset\nunset object\n";
}

void GnuplotBatch::run() {
  const std::filesystem::path script = dir_ / "charts.gp";
  const std::filesystem::path log = dir_ / "gnuplot.log";
  std::ofstream(script) << script_;
  const std::string command =
      fmt::format("cd '{}' && gnuplot charts.gp >gnuplot.log 2>&1", dir_.string());
  const int status = std::system(command.c_str());
  if (status != 0) {
    const std::string output = readBytes(log);
    throw SetupError(fmt::format("gnuplot failed ({}): {}; install gnuplot-nox (ci/packages.txt)",
                                 WIFEXITED(status) ? WEXITSTATUS(status) : -1,
                                 output.substr(0, 2000)));
  }
}

std::string readBytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

}  // namespace snell
