#pragma once
// Every chart of a report drawn by one gnuplot process: starting gnuplot
// costs more than most plots, so the plots are collected into one script
// (each with its own `set output`) and run once.
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace snell {

class GnuplotBatch {
 public:
  // The script and gnuplot's output, left in the work folder to read.
  static constexpr const char* kScript = "charts.gp";
  static constexpr const char* kLog = "gnuplot.log";
  // What each output is drawn to first, beside it: OUTPUT.drawing.
  static constexpr const char* kDrawing = ".drawing";

  // Data and outputs live in `workDir`, which must exist.
  explicit GnuplotBatch(std::filesystem::path workDir);

  // A fresh file name in the work folder, e.g. file("hist", ".svg").
  std::filesystem::path file(const std::string& stem, const std::string& extension);
  // One plot: commands that set the terminal, the output and plot. Settings
  // are reset after it, so plots do not leak into each other.
  void add(const std::string& commands);
  // Runs gnuplot on the script; throws SetupError with gnuplot's message
  // when it is missing, fails or is stopped by a signal. Each chart is
  // drawn under a temporary name and renamed over its file only when every
  // chart was drawn: a chart from an earlier run is never left empty or
  // half drawn, nor a new one beside old ones.
  void run();

 private:
  std::filesystem::path dir_;
  std::string script_;
  int files_ = 0;
  std::vector<std::pair<std::filesystem::path, std::filesystem::path>> outputs_;  // drawn, final
};

// Reads a whole file as bytes; empty when it is missing.
std::string readBytes(const std::filesystem::path& path);

}  // namespace snell
