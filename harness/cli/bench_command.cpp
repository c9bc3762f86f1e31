#include <fmt/format.h>

#include <cstdio>
#include <filesystem>

#include "bench/ablation.h"
#include "bench/angle_chart.h"
#include "bench/bench_chart.h"
#include "bench/bench_record.h"
#include "bench/bench_runner.h"
#include "bench/bench_table.h"
#include "bench/ladder_checks.h"
#include "bench/wavelength_chart.h"
#include "cli/commands.h"

namespace snell::cli {

Command addBenchCommand(CLI::App& app) {
  CLI::App* bench = app.add_subcommand(
      "bench",
      "Time each method listing on each backend and measure its error against the physics "
      "reference: JSON, a table, and the error-against-time chart with the Pareto front");
  struct Options {
    bench::BenchOptions run;
    std::string out = defaultBenchDir();
    std::string metric = "de_mean";
    bool ablation = true;
  };
  auto options = std::make_shared<Options>();
  options->run.methodsDir = defaultMethodsDir();
  bench->add_option("--methods", options->run.methodsDir,
                    "Folder of method manifests (default: the Fresnel ladder; "
                    "shaders/methods/dispersion is the dispersion ladder)");
  bench->add_option("--scene", options->run.scene, "Scene to draw (the reference models `sphere`)");
  bench->add_option("--backends", options->run.backends, "Backends to time, e.g. gl vk")
      ->delimiter(',');
  bench
      ->add_option("--resolutions", options->run.resolutions,
                   "Square image sizes in pixels; the error is measured at the last")
      ->delimiter(',');
  bench->add_option("--repeats", options->run.repeats, "Timed frames per resolution");
  bench->add_option("--warmup", options->run.warmup, "Untimed frames after the first draw");
  bench->add_option("--reference-wavelengths", options->run.referenceWavelengths,
                    "Wavelengths of a dispersion ladder's spectral reference");
  bench->add_option("--out", options->out,
                    "Output folder: bench.json, pareto.svg, pareto.png, images/");
  bench->add_option("--metric", options->metric,
                    "Error on the chart's axis and for the table's front: rms, max, de_mean, "
                    "de_p95");
  bench->add_flag("!--no-ablation", options->ablation,
                  "Skip the ablation table of the physics reference");
  bench->footer(
      "Time per frame: a render (draw and RGBA32F read-back), median of warm repeats after the "
      "pipeline is compiled, with the 10th-90th percentile spread. Error: RMS and largest "
      "channel difference in linear RGB, mean and 95th percentile CIEDE2000, at the largest "
      "resolution, over the pixels both images cover. Timing is measured, never asserted.");
  return [options] {
    bench::errorMetric({}, options->metric);  // refuse an unknown metric before drawing
    const std::filesystem::path out = options->out;
    std::filesystem::create_directories(out / "images");
    options->run.imagesDir = out / "images";
    const bench::BenchResults results = bench::runBench(
        options->run, [](const std::string& line) { fmt::print(stderr, "{}\n", line); });
    bench::writeBenchResults(results, out / "bench.json");
    fmt::print("{}", bench::benchTable(results, options->metric));
    bench::drawParetoChart(results, options->metric, out);
    bench::drawAngleChart(results, options->metric, out);
    std::string charts =
        fmt::format("{0}/pareto.svg, {0}/pareto.png, {0}/angle.svg, {0}/angle.png", out.string());
    if (bench::hasWavelengthCounts(results)) {
      const auto violations = bench::wavelengthOrderViolations(results, options->metric,
                                                               bench::errorNoise(options->metric));
      if (violations.empty())
        fmt::print(
            "More wavelengths never moved a method away from the reference by more than "
            "{:.3g} ({}).\n",
            bench::errorNoise(options->metric), options->metric);
      for (const std::string& v : violations) fmt::print("ORDER: {}\n", v);
      bench::drawWavelengthChart(results, options->metric, out);
      charts += fmt::format(", {0}/wavelengths.svg, {0}/wavelengths.png", out.string());
    }
    std::string files = fmt::format("{}/bench.json", out.string());
    if (options->ablation) {
      const bench::AblationTable table =
          bench::ablationTable(makeScene(options->run.scene), options->run.resolutions.back());
      fmt::print("{}", bench::ablationText(table));
      bench::writeAblationJson(table, out / "ablation.json");
      files += fmt::format(", {}/ablation.json", out.string());
    }
    fmt::print("wrote {}, {}\n", files, charts);
    return 0;
  };
}

}  // namespace snell::cli
