#include <fmt/format.h>
#include <fmt/ranges.h>

#include <set>

#include "cli/commands.h"
#include "core/case.h"

namespace snell::cli {

Command addListCommand(CLI::App& app) {
  CLI::App* list = app.add_subcommand("list", "List the cases: id, backends, expected status, source");
  struct Options {
    std::string shaders = defaultShadersDir();
    std::string filter;
  };
  auto options = std::make_shared<Options>();
  list->add_option("--shaders", options->shaders, "Folder of listings")->check(CLI::ExistingDirectory);
  list->add_option("--filter", options->filter, "Only cases whose id matches this glob");
  return [options] {
    const std::vector<Manifest> manifests = loadManifests(options->shaders);
    const std::vector<Case> cases = expandCases(manifests, options->filter);
    std::size_t width = 4;
    for (const Case& c : cases) width = std::max(width, c.id.size());
    fmt::print("{:<{}}  {:<8}  {:<8}  {:<13}  {:<22}  {}\n", "case", width, "backends", "expected",
               "checks", "oracle", "source");
    for (const Case& c : cases)
      fmt::print("{:<{}}  {:<8}  {:<8}  {:<13}  {:<22}  {} ({})\n", c.id, width, "gl,vk", "Pass",
                 fmt::format("{}", fmt::join(c.spec.checks, ",")), c.manifest->oracle,
                 c.manifest->source.file, c.manifest->source.where);
    std::set<const Manifest*> listings;
    for (const Case& c : cases) listings.insert(c.manifest);
    fmt::print("{} cases from {} listings\n", cases.size(), listings.size());
    return 0;
  };
}

}  // namespace snell::cli
