#include <fmt/format.h>

#include <limits>
#include <nlohmann/json.hpp>

#include "bench/advisor.h"
#include "bench/bench_chart.h"
#include "bench/bench_record.h"
#include "cli/commands.h"
#include "cli/option_checks.h"
#include "core/errors.h"
#include "runner/json_fields.h"

namespace snell::cli {
namespace {

nlohmann::json recordJson(const std::optional<bench::BenchRecord>& r, const std::string& metric) {
  if (!r) return nullptr;
  return {{"method", r->method},
          {"ms_per_frame", r->msPerFrame()},
          {"error", bench::errorMetric(r->error, metric)},
          {"rms", r->error.rms},
          {"de_mean", r->error.deMean},
          {"de_p95", r->error.deP95}};
}

// The error to four digits, or to as many as it takes to differ from
// `budget` where it is not equal to it ("no method within 0.0569; the most
// accurate is 0.0569" read as a contradiction).
std::string recordText(const bench::BenchRecord& r, const std::string& metric,
                       double budget = std::numeric_limits<double>::quiet_NaN()) {
  const double error = bench::errorMetric(r.error, metric);
  int digits = 4;
  while (digits < 17 && error != budget &&
         fmt::format("{:.{}g}", error, digits) == fmt::format("{:.{}g}", budget, digits))
    ++digits;
  return fmt::format("{} ({:.3f} ms per frame, {} {:.{}g})", bench::shortMethodName(r.method),
                     r.msPerFrame(), metric, error, digits);
}

}  // namespace

Command addAdviseCommand(CLI::App& app) {
  CLI::App* advise = app.add_subcommand(
      "advise",
      "Name the cheapest measured method whose error stays within a budget (from "
      "`snell bench` results)");
  struct Options {
    std::string scene;
    double budget = 0;
    std::string metric = "de_mean";
    std::string ladder = "fresnel";
    std::string results;
    std::string backend;
    bool json = false;
  };
  auto options = std::make_shared<Options>();
  advise->add_option("--scene", options->scene, "The scene the methods were measured on")
      ->required();
  advise
      ->add_option("--budget", options->budget, "The largest error allowed, in the metric's units")
      ->check(number("the largest error allowed, in the metric's units (e.g. 1.0 for de_mean)"))
      ->required();
  advise->add_option("--metric", options->metric, "rms, max, de_mean (default) or de_p95");
  CLI::Option* ladder = advise->add_option(
      "--ladder", options->ladder,
      "The method ladder: fresnel (default), dispersion, refraction or a ladder of your own; its "
      "results are read from " +
          defaultBenchDir() + "/LADDER/bench.json");
  advise
      ->add_option("--results", options->results,
                   "A `snell bench` bench.json (in place of the ladder's default)")
      ->check(nonEmptyPath());
  advise->add_option("--backend", options->backend, "Only this backend (default: each measured)")
      ->check(nonEmpty("backend", "name one"));
  advise->add_flag("--json", options->json, "One JSON object on standard output, for scripts");
  advise->footer("Exit code 0 when every backend has a method within budget, 1 when one has none.");
  return [options, ladder] {
    // --results replaces the ladder's file: both given, one would be
    // passed over (advice on Fresnel methods asked for dispersion).
    if (ladder->count() > 0 && !options->results.empty())
      throw UsageError(
          fmt::format("--ladder {} and --results {} both say which results to read: "
                      "give one",
                      options->ladder, options->results));
    const bench::BenchResults results = bench::readBenchResults(
        options->results.empty() ? defaultBenchDir() + "/" + options->ladder + "/bench.json"
                                 : options->results);
    const std::vector<bench::Advice> advice =
        bench::advise(results, options->scene, options->budget, options->metric, options->backend);
    bool allMet = true;
    nlohmann::json doc{{"scene", options->scene},
                       {"budget", options->budget},
                       {"metric", options->metric},
                       {"backends", nlohmann::json::array()}};
    for (const bench::Advice& a : advice) {
      allMet = allMet && a.choice.has_value();
      doc["backends"].push_back({{"backend", a.backend},
                                 {"choice", recordJson(a.choice, options->metric)},
                                 {"runner_up", recordJson(a.runnerUp, options->metric)},
                                 {"most_accurate", recordJson(a.mostAccurate, options->metric)}});
      if (options->json) continue;
      if (a.choice) {
        fmt::print("{}: {}", a.backend, recordText(*a.choice, options->metric));
        if (a.runnerUp) fmt::print("; runner-up {}", recordText(*a.runnerUp, options->metric));
        fmt::print("\n");
      } else {
        fmt::print("{}: no method within {} {}; the most accurate is {}\n", a.backend,
                   options->metric, options->budget,
                   recordText(*a.mostAccurate, options->metric, options->budget));
      }
    }
    if (options->json) fmt::print("{}\n", jsonText(doc, 2));
    return allMet ? 0 : 1;
  };
}

}  // namespace snell::cli
