// snell_widths: how wide snell's intervals are beside a dEQP-style interval
// computed in the same run, per built-in input set and per listing output,
// and whether conforming values escape either (bench/widths/README.md).
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <iostream>

#include "core/errors.h"
#include "core/message.h"
#include "widths/inputs.h"
#include "widths/measure.h"
#include "widths/report.h"

namespace {

using namespace snell;
using namespace snell::widths;

struct Options {
  std::string json, before, shaders = SNELL_WIDTHS_SHADERS;
  bool check = false, builtinsOnly = false;
  std::size_t samples = 2000, vertices = 200, conforming = 12;
  std::uint64_t seed = 9;
};

WidthReport measure(const Options& options) {
  WidthReport report;
  report.oracle = snellOracleVersion();
  for (const PrecisionRules rules : {PrecisionRules::Glsl, PrecisionRules::Vulkan}) {
    for (const BuiltinInputSet& set : builtinInputSets(options.samples, options.seed)) {
      RowAccumulator row(fmt::format("{} / {}", set.fn, set.name), rules);
      std::uint64_t seed = options.seed;
      for (const BuiltinInput& input : set.inputs)
        row.add(
            builtinRecord(set.fn, input.I, input.N, input.eta, rules, options.conforming, ++seed));
      report.rows.push_back(row.finish());
    }
    if (options.builtinsOnly) continue;
    for (const ListingInputSet& set :
         listingInputSets(options.shaders, options.vertices, options.seed)) {
      const auto records =
          listingRecords(set.oracle, set.bindings, rules, options.conforming, options.seed);
      const std::vector<std::string> names = snellListingOutputs(set.oracle);
      for (std::size_t output = 0; output < records.size(); ++output) {
        if (names[output] == "gl_Position") continue;  // not a listing output
        RowAccumulator row(fmt::format("{} / {}", set.manifest, names[output]), rules);
        for (const SampleRecord& record : records[output]) row.add(record);
        report.rows.push_back(row.finish());
      }
    }
  }
  return report;
}

int run(const Options& options) {
  const WidthReport report = measure(options);
  printTable(std::cout, report);
  if (!options.json.empty()) writeJson(options.json, report);
  if (!options.before.empty()) {
    std::cout << "\n";
    printComparison(std::cout, readJson(options.before), report);
  }
  if (!options.check) return 0;
  const auto unsound = unsoundRows(report);
  for (const RowStats* r : unsound)
    printMessage(stderr,
                 "unsound: {} ({}): {} conforming values outside snell's interval, none "
                 "outside the dEQP-style one; first: {}\n",
                 r->row, r->rules, r->snellEscapes, r->snellEscape);
  return unsound.empty() ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  CLI::App app{"Interval widths: snell's oracle beside a dEQP-style interval"};
  app.add_option("--json", options.json, "write the rows as JSON to FILE");
  app.add_option("--before", options.before, "compare with a JSON written earlier");
  app.add_flag(
      "--check", options.check,
      "exit 1 where snell lets a conforming value escape and the dEQP-style interval does not");
  app.add_option("--samples", options.samples, "inputs per built-in set")
      ->check(CLI::PositiveNumber);
  app.add_option("--vertices", options.vertices, "inputs per listing")->check(CLI::PositiveNumber);
  app.add_option("--conforming", options.conforming, "conforming values per input")
      ->check(CLI::PositiveNumber);
  app.add_option("--seed", options.seed, "random seed");
  app.add_option("--shaders", options.shaders, "the catalog folder")->check(CLI::ExistingDirectory);
  app.add_flag("--builtins-only", options.builtinsOnly, "only reflect and refract");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    return app.exit(error) == 0 ? 0 : 2;
  }
  try {
    return run(options);
  } catch (const UsageError& error) {
    snell::printMessage(stderr, "snell_widths: {}\n", error.what());
    return 2;
  } catch (const std::exception& error) {
    snell::printMessage(stderr, "snell_widths: {}\n", error.what());
    return 2;
  }
}
