#include <fmt/format.h>

#include <cstdio>
#include <filesystem>

#include "bench/bench_chart.h"
#include "bench/bench_record.h"
#include "bench/bench_runner.h"
#include "bench/bench_table.h"
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
  };
  auto options = std::make_shared<Options>();
  options->run.methodsDir = defaultMethodsDir();
  bench->add_option("--methods", options->run.methodsDir,
                    "Folder of method manifests (default: the Fresnel ladder)");
  bench->add_option("--scene", options->run.scene, "Scene to draw (the reference models `sphere`)");
  bench->add_option("--backends", options->run.backends, "Backends to time, e.g. gl vk")
      ->delimiter(',');
  bench
      ->add_option("--resolutions", options->run.resolutions,
                   "Square image sizes in pixels; the error is measured at the last")
      ->delimiter(',');
  bench->add_option("--repeats", options->run.repeats, "Timed frames per resolution");
  bench->add_option("--warmup", options->run.warmup, "Untimed frames after the first draw");
  bench->add_option("--out", options->out,
                    "Output folder: bench.json, pareto.svg, pareto.png, images/");
  bench->add_option("--metric", options->metric,
                    "Error on the chart's axis and for the table's front: rms, max, de_mean, "
                    "de_p95");
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
    fmt::print("wrote {0}/bench.json, {0}/pareto.svg, {0}/pareto.png\n", out.string());
    return 0;
  };
}

}  // namespace snell::cli
