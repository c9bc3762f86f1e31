#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <set>
#include <system_error>

#include "bench/ablation.h"
#include "bench/angle_chart.h"
#include "bench/bench_chart.h"
#include "bench/bench_record.h"
#include "bench/bench_runner.h"
#include "bench/bench_table.h"
#include "bench/ladder_checks.h"
#include "bench/sphere_view.h"
#include "bench/vertex_chart.h"
#include "bench/wavelength_chart.h"
#include "cli/backend_options.h"
#include "cli/commands.h"
#include "cli/option_checks.h"
#include "cli/output_paths.h"
#include "core/atomic_file.h"
#include "core/errors.h"
#include "core/message.h"
#include "runner/interrupt_flag.h"

namespace snell::cli {

namespace {

// A folder with a method manifest one level down.
bool isLadder(const std::filesystem::path& dir) {
  if (!std::filesystem::is_directory(dir))
    throw UsageError(fmt::format("{}: no such folder of methods", dir.string()));
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    if (entry.is_directory() && std::filesystem::exists(entry.path() / "manifest.toml"))
      return true;
  return false;
}

// The names of the charts' data files (bench_chart.cpp, angle_chart.cpp,
// vertex_chart.cpp, wavelength_chart.cpp): PREFIX<backend>....dat.
bool isChartData(const std::string& name) {
  if (!name.ends_with(".dat")) return false;
  for (const char* prefix :
       {"points_", "front_", "angle_", "vertices_", "spectral_", "per_channel_"})
    if (name.starts_with(prefix)) return true;
  return false;
}

// An image named as the bench names them (bench::benchImageName):
// STEM.BACKEND.exr, BACKEND one of snell's.
bool isBenchImage(const std::string& name) {
  if (!name.ends_with(".exr")) return false;
  const std::string stem = name.substr(0, name.size() - 4);
  const std::size_t dot = stem.rfind('.');
  return dot != std::string::npos && dot > 0 && unknownBackendReason(stem.substr(dot + 1)).empty();
}

// A ladder's folder is the bench's own: an earlier run's charts, their data
// and its images of methods or backends this run did not measure would
// stand beside the new bench.json and contradict it. Once the new results
// are written, the chart data (written whole by each chart), the charts
// this run may not draw again, and the images it did not write go. Files
// not named as the bench names its own stay.
void removeEarlierOutputs(const bench::BenchResults& results, const std::filesystem::path& out) {
  namespace fs = std::filesystem;
  std::error_code error;
  std::vector<fs::path> stale;
  for (const fs::directory_entry& entry : fs::directory_iterator(out, error))
    if (isChartData(entry.path().filename().string()) && entry.is_regular_file(error))
      stale.push_back(entry.path());
  for (const char* chart : {"vertices", "wavelengths"})
    for (const char* extension : {".svg", ".png"})
      stale.push_back(out / (std::string(chart) + extension));
  std::set<std::string> images = {bench::kReferenceImageName};
  for (const bench::BenchRecord& r : results.records)
    images.insert(bench::benchImageName(r.method, r.backend));
  for (const fs::directory_entry& entry : fs::directory_iterator(out / "images", error))
    if (const std::string name = entry.path().filename().string();
        isBenchImage(name) && !images.count(name))
      stale.push_back(entry.path());
  for (const fs::path& path : stale) fs::remove(path, error);
}

// A ladder's new images, written to a folder beside images/ and moved into
// it once bench.json is written: a bench stopped before then (Ctrl-C, a
// method that fails) leaves the earlier run's images with the earlier
// bench.json they go with. The folder goes when this does.
class StagedImages {
 public:
  explicit StagedImages(const std::filesystem::path& out)
      : images_(out / "images"), staging_(temporaryPathFor(images_)) {
    std::filesystem::create_directories(images_);
    std::filesystem::create_directories(staging_);
  }
  ~StagedImages() {
    std::error_code ignored;
    std::filesystem::remove_all(staging_, ignored);
  }
  StagedImages(const StagedImages&) = delete;
  StagedImages& operator=(const StagedImages&) = delete;

  const std::filesystem::path& folder() const { return staging_; }

  // Moves each image into images/, over the earlier run's of its name.
  void moveIntoPlace() const {
    for (const std::filesystem::directory_entry& entry :
         std::filesystem::directory_iterator(staging_)) {
      const std::filesystem::path target = images_ / entry.path().filename();
      std::error_code error;
      std::filesystem::rename(entry.path(), target, error);
      if (error)
        throw SetupError(fmt::format("{}: cannot move the new image there ({}); check --out",
                                     target.string(), error.message()));
    }
  }

 private:
  std::filesystem::path images_, staging_;
};

// Measures one ladder into `out`: bench.json, its table, its charts; returns
// the line naming what it wrote.
std::string measureLadder(bench::BenchOptions run, const std::filesystem::path& out,
                          const std::string& metric) {
  const StagedImages images(out);
  run.imagesDir = images.folder();
  const bench::BenchResults results =
      bench::runBench(run, [](const std::string& line) { printMessage(stderr, "{}\n", line); });
  bench::writeBenchResults(results, out / "bench.json");
  images.moveIntoPlace();
  fmt::print("{}", bench::benchTable(results, metric));
  removeEarlierOutputs(results, out);
  bench::drawParetoChart(results, metric, out);
  bench::drawAngleChart(results, metric, out);
  std::string charts =
      fmt::format("{0}/pareto.svg, {0}/pareto.png, {0}/angle.svg, {0}/angle.png", out.string());
  if (bench::hasTessellations(results)) {
    bench::drawVertexChart(results, out);
    charts += fmt::format(", {0}/vertices.svg, {0}/vertices.png", out.string());
  }
  if (bench::hasWavelengthCounts(results)) {
    const double noise = bench::errorNoise(metric);
    const auto violations = bench::wavelengthOrderViolations(results, metric, noise);
    if (violations.empty())
      fmt::print(
          "More wavelengths never moved a method away from the reference by more than "
          "{:.3g} ({}).\n",
          noise, metric);
    for (const std::string& v : violations) fmt::print("ORDER: {}\n", v);
    bench::drawWavelengthChart(results, metric, out);
    charts += fmt::format(", {0}/wavelengths.svg, {0}/wavelengths.png", out.string());
  }
  fmt::print("\n");
  return fmt::format("wrote {}/bench.json, {}\n", out.string(), charts);
}

// The same, leaving no folder behind that it made when it fails (an
// earlier ladder's results in the same --out are kept).
std::string benchLadder(const bench::BenchOptions& run, const std::filesystem::path& out,
                        const std::string& metric) {
  const std::filesystem::path made = firstMissingFolder(out);
  try {
    return measureLadder(run, out, metric);
  } catch (...) {
    std::error_code ignored;
    if (!made.empty()) std::filesystem::remove_all(made, ignored);
    throw;
  }
}

}  // namespace

Command addBenchCommand(CLI::App& app) {
  CLI::App* bench = app.add_subcommand(
      "bench",
      "Time each method listing on each backend and measure its error against the physics "
      "reference: JSON, a table, and the error-against-time chart with the Pareto front");
  struct Options {
    bench::BenchOptions run;
    std::string out = defaultBenchDir();
    std::string metric = "de_mean";
    bool noAblation = false;
  };
  auto options = std::make_shared<Options>();
  options->run.methodsDir = defaultMethodsDir();
  bench->add_option("--methods", options->run.methodsDir,
                    "A ladder (a folder of method folders, e.g. shaders/methods/dispersion) or a "
                    "folder of ladders, each written to OUT/LADDER (default: shaders/methods, "
                    "every ladder)");
  bench->add_option("--scene", options->run.scene, "Scene to draw (the reference models `sphere`)");
  bench->add_option("--backends", options->run.backends, "Backends to time, e.g. gl,vk")
      ->delimiter(',')
      ->capture_default_str();
  addWholeNumberList(*bench, "--resolutions", options->run.resolutions,
                     "Square image sizes in pixels; the error is measured at the last",
                     "list of sizes", "give sizes in pixels, e.g. 128,256,512");
  addWholeNumberList(*bench, "--tessellations", options->run.tessellations,
                     "Sphere tessellations to time at the largest resolution, as stacks (slices "
                     "in the scene's ratio, 2 per stack on `sphere`): how the time grows with the "
                     "vertex count (default: the scene's own, a quarter and four times it; the "
                     "error is measured at the scene's own)",
                     "list of stacks", "give stacks, e.g. 12,48,192");
  // Ranges stated here: past int, CLI11 says only "Could not convert".
  bench->add_option("--repeats", options->run.repeats, "Timed frames per resolution")
      ->check(wholeNumber())
      ->check(CLI::Range(1, 100000))
      ->capture_default_str();
  bench->add_option("--warmup", options->run.warmup, "Untimed frames after the first draw")
      ->check(wholeNumber())
      ->check(CLI::Range(0, 100000))
      ->capture_default_str();
  bench
      ->add_option("--reference-wavelengths", options->run.referenceWavelengths,
                   "Wavelengths of a dispersion ladder's spectral reference")
      ->capture_default_str();
  CLI::Option* outOption =
      bench
          ->add_option("--out", options->out,
                       "Output folder: per ladder bench.json, pareto.svg/png, angle.svg/png, "
                       "vertices.svg/png, wavelengths.svg/png, images/; ablation.json (one "
                       "--methods ladder without --out: OUT/LADDER, where `advise` reads it)")
          ->capture_default_str()
          ->check(nonEmptyPath());
  bench
      ->add_option("--metric", options->metric,
                   "Error on the chart's axis and for the table's front: rms, max, de_mean, "
                   "de_p95")
      ->capture_default_str();
  bench->add_flag("--no-ablation", options->noAblation,
                  "Skip the ablation table of the physics reference");
  bench->footer(
      "Time per frame: a render (draw and RGBA32F read-back), median of warm repeats after the "
      "pipeline is compiled, with the 10th-90th percentile spread. Error: RMS and largest "
      "channel difference in linear RGB, mean and 95th percentile CIEDE2000, at the largest "
      "resolution, over the pixels both images cover. Timing is measured, never asserted.");
  return [options, outOption] {
    bench::errorMetric({}, options->metric);  // refuse an unknown metric before drawing
    // Another scene, known or not, is refused for that reason alone.
    bench::requireSphereScene(options->run.scene);
    // Each backend once: a second timing of it would be a second record
    // under one key, which `advise` refuses.
    const std::vector<std::string>& backends = options->run.backends;
    for (auto it = backends.begin(); it != backends.end(); ++it)
      if (std::find(backends.begin(), it, *it) != it)
        throw UsageError(
            fmt::format("--backends: `{}` is named twice; name each backend once", *it));
    // The error and the front are taken at the last size, which the table
    // and the charts call the largest.
    const std::vector<int>& sizes = options->run.resolutions;
    if (std::adjacent_find(sizes.begin(), sizes.end(), std::greater_equal<int>()) != sizes.end())
      throw UsageError(fmt::format(
          "--resolutions {}: give them in increasing order, each once (the error is measured "
          "at the largest, the last)",
          fmt::join(sizes, ",")));
    checkOutputs({}, {{"--out", options->out}});
    const std::filesystem::path out = options->out;
    // A folder of ladders (each a folder of method folders) runs each into
    // a folder of its own; a folder of methods is one ladder.
    std::vector<std::pair<std::filesystem::path, std::filesystem::path>> ladders;
    if (isLadder(options->run.methodsDir)) {
      // Without --out, one ladder goes where `advise --ladder` reads it,
      // as each of a folder of ladders does.
      ladders.push_back(
          {options->run.methodsDir,
           outOption->count() > 0
               ? out
               : out / std::filesystem::weakly_canonical(options->run.methodsDir).filename()});
    } else {
      for (const auto& entry : std::filesystem::directory_iterator(options->run.methodsDir))
        if (entry.is_directory() && isLadder(entry.path()))
          ladders.push_back({entry.path(), out / entry.path().filename()});
      std::sort(ladders.begin(), ladders.end());
    }
    if (ladders.empty() && std::filesystem::exists(options->run.methodsDir / "manifest.toml"))
      throw UsageError(fmt::format(
          "{}: one method (its manifest.toml), not a ladder of methods; give --methods the "
          "folder that holds it ({})",
          options->run.methodsDir.string(),
          std::filesystem::weakly_canonical(options->run.methodsDir).parent_path().string()));
    if (ladders.empty())
      throw UsageError(fmt::format("{}: no method manifests (manifest.toml) found here",
                                   options->run.methodsDir.string()));
    // Every ladder's manifests and output paths before any is timed: a
    // file where a ladder's folder, images or bench.json go was found after
    // its measurement, as an internal error.
    std::vector<OutputPath> ladderFiles, ladderFolders;
    for (const auto& [methods, dir] : ladders) {
      bench::BenchOptions run = options->run;
      run.methodsDir = methods;
      (void)bench::loadLadder(run);
      ladderFolders.push_back({"--out", dir});
      ladderFolders.push_back({"--out", dir / "images"});
      // (A folder still to be made holds no file yet.)
      if (std::filesystem::is_directory(dir)) ladderFiles.push_back({"--out", dir / "bench.json"});
    }
    checkOutputs(ladderFiles, ladderFolders);
    std::string files;
    // Ctrl-C stops the bench before its next method (bench_runner.cpp).
    const InterruptFlag interrupt;
    for (const auto& [methods, dir] : ladders) {
      bench::BenchOptions run = options->run;
      run.methodsDir = methods;
      files += benchLadder(run, dir, options->metric);
    }
    if (!options->noAblation) {
      const bench::AblationTable table =
          bench::ablationTable(makeScene(options->run.scene), options->run.resolutions.back());
      fmt::print("{}", bench::ablationText(table));
      bench::writeAblationJson(table, out / "ablation.json");
      files += fmt::format("wrote {}/ablation.json\n", out.string());
    }
    fmt::print("{}", files);
    return 0;
  };
}

}  // namespace snell::cli
