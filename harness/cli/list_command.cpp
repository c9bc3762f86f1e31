#include <fmt/format.h>
#include <fmt/ranges.h>

#include <set>

#include "cli/case_filter.h"
#include "cli/commands.h"
#include "cli/option_checks.h"
#include "core/case.h"
#include "core/errors.h"
#include "core/status.h"
#include "runner/case_validation.h"
#include "runner/listing_oracles.h"

namespace snell::cli {

Command addListCommand(CLI::App& app) {
  CLI::App* list =
      app.add_subcommand("list", "List the cases: id, backends, expected status, source");
  struct Options {
    std::string shaders = defaultShadersDir();
    std::string filter;
    bool check = false;
  };
  auto options = std::make_shared<Options>();
  list->add_option("--shaders", options->shaders, "Folder of listings")
      ->check(CLI::ExistingDirectory)
      ->capture_default_str();
  list->add_option("--filter", options->filter, "Only cases whose id matches this glob")
      ->check(nonEmptyGlob());
  // Listing reads the manifests only; the deeper checks (the scenes built,
  // the listings parsed for the derived oracle) are `run`'s first step, and
  // cost a listing ten times its own time.
  list->add_flag(
      "--check", options->check,
      "Also check every case as `run` does before it starts (scenes, captures, oracles)");
  return [options] {
    const std::vector<Manifest> manifests = loadCatalog(options->shaders);
    const std::vector<Case> cases = expandCases(manifests, options->filter);
    // As `run` does: a filter that matches nothing is a mistake, not an
    // empty catalog.
    if (cases.empty() && !options->filter.empty())
      throw UsageError(noCaseMatchesMessage(manifests, options->filter));
    if (options->check) validateCases(cases, options->shaders);
    std::size_t width = 4;
    for (const Case& c : cases) width = std::max(width, c.id.size());
    fmt::print("{:<{}}  {:<8}  {:<20}  {:<8}  {:<13}  {:<26}  {}\n", "case", width, "backends",
               "expected", "stage", "checks", "oracle", "source");
    for (const Case& c : cases) {
      const Manifest& m = *c.manifest;
      std::vector<std::string> backends;
      for (const char* backend : {"gl", "vk"})
        if (!m.notSupported.count(backend)) backends.emplace_back(backend);
      const char* stage = m.expect == Expectation::CompileError ? "-"
                          : m.captureFragment.empty()           ? "vertex"
                                                                : "fragment";
      fmt::print("{:<{}}  {:<8}  {:<20}  {:<8}  {:<13}  {:<26}  {} ({})\n", c.id, width,
                 fmt::format("{}", fmt::join(backends, ",")),
                 statusName(m.expect == Expectation::CompileError ? Status::ExpectedCompileError
                                                                  : Status::Pass),
                 stage, fmt::format("{}", fmt::join(c.spec.checks, ",")), oracleLabel(m),
                 m.source.file, m.source.where);
    }
    std::set<const Manifest*> listings;
    for (const Case& c : cases) listings.insert(c.manifest);
    for (const Manifest* m : listings)
      for (const auto& [backend, reason] : m->notSupported)
        fmt::print("{}: NotSupported on {}: {}\n", m->id, backend, reason);
    fmt::print("{} cases from {} listings\n", cases.size(), listings.size());
    return 0;
  };
}

}  // namespace snell::cli
