#include "baseline/merge_results.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <map>
#include <set>

#include "baseline/driver_build.h"
#include "baseline/shard.h"
#include "core/errors.h"

namespace snell {
namespace {

// Records say which shard of how many ran them, and of which run (its
// --filter and --backend): a merge that lacks one of a run's shards would be
// a run with cases missing and no word of it, also where another run's
// shard (another filter or backend list) stands in its place. Shards are
// counted per run over all files, not per backend: a shard may hold no
// record of a backend (its cases skipped there, or the backend not up on
// that runner), and each backend may be a run of its own, sharded apart. A
// file with no results (a shard with no cases) may stand for any one shard;
// records of a whole run, or written before records named their shard, say
// nothing and are not counted.
// A run's shards, as the records name them: (the run's selection, shard
// count N) -> shard index I -> the cases its records hold. Records written
// before records named their run (no shard_of) count for every run of
// their N.
using ShardsOfRuns =
    std::map<std::pair<std::string, std::size_t>, std::map<std::size_t, std::set<std::string>>>;

ShardsOfRuns shardsOfRuns(const std::vector<ResultsFile>& files) {
  ShardsOfRuns seen;
  std::map<std::size_t, std::map<std::size_t, std::set<std::string>>> unnamed;  // by N
  for (const ResultsFile& file : files)
    for (const CaseResult& r : file.results)
      if (!r.shard.empty()) {
        const Shard shard = parseShard(r.shard);
        if (r.shardOf.empty())
          unnamed[shard.count][shard.index].insert(r.caseId);
        else
          seen[{r.shardOf, shard.count}][shard.index].insert(r.caseId);
      }
  for (const auto& [count, shards] : unnamed) {
    bool joined = false;
    for (auto& [run, named] : seen)
      if (run.second == count) {
        for (const auto& [index, cases] : shards) named[index].insert(cases.begin(), cases.end());
        joined = true;
      }
    if (!joined) seen[{"", count}] = shards;
  }
  return seen;
}

std::string ofTheRun(const std::string& selection) {
  return selection.empty() ? std::string() : fmt::format(" of the run of {}", selection);
}

// Records say which shard of how many ran them, and of which run (its
// --filter and --backend): a merge that lacks one of a run's shards would be
// a run with cases missing and no word of it, also where another run's
// shard (another filter or backend list) stands in its place. Shards are
// counted per run over all files, not per backend: a shard may hold no
// record of a backend (its cases skipped there, or the backend not up on
// that runner), and each backend may be a run of its own, sharded apart. A
// file with no results (a shard with no cases) may stand for any one shard;
// records of a whole run, or written before records named their shard, say
// nothing and are not counted.
void requireEveryShard(const std::vector<ResultsFile>& files) {
  const std::size_t emptyFiles = static_cast<std::size_t>(std::count_if(
      files.begin(), files.end(), [](const ResultsFile& f) { return f.results.empty(); }));
  // Every run that lacks shards is named: where a shard of another run was
  // given in place of one, both runs are. An empty file is one shard of one
  // run: it stands for one missing shard in all.
  std::vector<std::string> lacking;
  std::size_t missingShards = 0;
  for (const auto& [run, shards] : shardsOfRuns(files)) {
    const auto& [selection, count] = run;
    std::vector<std::string> missing;
    for (std::size_t i = 1; i <= count; ++i)
      if (!shards.contains(i)) missing.push_back(fmt::format("{}/{}", i, count));
    if (missing.empty()) continue;
    missingShards += missing.size();
    lacking.push_back(fmt::format("shard {}{}", fmt::join(missing, ", "), ofTheRun(selection)));
  }
  if (missingShards > emptyFiles)
    throw UsageError(fmt::format(
        "no results of {}{}: merge every shard's results file (an empty one counts), or run the "
        "missing shard with the same --filter and --backend",
        fmt::join(lacking, "; nor of "),
        emptyFiles == 0   ? std::string()
        : emptyFiles == 1 ? std::string(" (the empty file stands for one)")
                          : fmt::format(" ({} empty files stand for others)", emptyFiles)));
}

}  // namespace

std::vector<CaseResult> mergeResults(const std::vector<ResultsFile>& files,
                                     const std::vector<Case>& catalog) {
  std::map<std::string, std::size_t> caseOrder;
  for (const Case& c : catalog) caseOrder.emplace(c.id, caseOrder.size());
  std::map<std::pair<std::string, std::size_t>, std::pair<const CaseResult*, const std::string*>>
      merged;
  // The first record of each backend that names its driver, and its file.
  std::map<std::string, std::pair<const CaseResult*, const std::string*>> driverOf;
  for (const ResultsFile& file : files)
    for (const CaseResult& r : file.results) {
      const auto [first, firstSeen] = driverOf.emplace(r.backend, std::pair(&r, &file.path));
      if (!firstSeen && !sameDriverBuild(first->second.first->driver, r.driver))
        throw UsageError(fmt::format(
            "{} ran {} on {}, and {} on {}: a merge joins the shards of one run; merge each "
            "driver build's results apart and compare them",
            *first->second.second, r.backend, driverBuildName(first->second.first->driver),
            file.path, driverBuildName(r.driver)));
      if (!firstSeen && !namesDriver(first->second.first->driver))
        first->second = std::pair(&r, &file.path);
      const auto order = caseOrder.find(r.caseId);
      if (order == caseOrder.end())
        throw UsageError(
            fmt::format("{}: case {} is not in the catalog; pass the --shaders "
                        "folder the run used",
                        file.path, r.caseId));
      const auto [it, added] =
          merged.emplace(std::pair(r.backend, order->second), std::pair(&r, &file.path));
      if (!added)
        throw UsageError(
            fmt::format("{} and {} both hold {} on {}: shards must not overlap; "
                        "merge the results of one run's shards only",
                        *it->second.second, file.path, r.caseId, r.backend));
    }
  requireEveryShard(files);
  std::vector<CaseResult> results;
  for (const auto& [key, value] : merged) {
    results.push_back(*value.first);
    results.back().shard.clear();  // the merge is the whole run
    results.back().shardOf.clear();
  }
  return results;
}

std::vector<std::string> notesOnEmptyShards(const std::vector<ResultsFile>& files) {
  std::vector<std::string> empty;
  for (const ResultsFile& file : files)
    if (file.results.empty()) empty.push_back(file.path);
  if (empty.empty()) return {};
  // Shard I of N holds cases I-1, I-1+N, ... of the run's list: where a
  // shard holds two cases, or a shard after I holds one, the list is longer
  // than I, so shard I had cases too.
  std::vector<std::string> notes;
  for (const auto& [run, shards] : shardsOfRuns(files)) {
    const auto& [selection, count] = run;
    std::size_t mostCases = 0;
    for (const auto& [index, cases] : shards) mostCases = std::max(mostCases, cases.size());
    for (std::size_t i = 1; i <= count; ++i) {
      if (shards.contains(i)) continue;
      const bool laterShardHasCases = shards.upper_bound(i) != shards.end();
      if (mostCases < 2 && !laterShardHasCases) continue;
      notes.push_back(fmt::format(
          "{} {} empty and stand{} for shard {}/{}{}, but shard {}/{} had cases (the other shards "
          "hold up to {} each): unless an expectations file skipped every one of them, its "
          "results are missing from this merge; merge its results file",
          fmt::join(empty, ", "), empty.size() == 1 ? "is" : "are", empty.size() == 1 ? "s" : "", i,
          count, ofTheRun(selection), i, count, mostCases));
    }
  }
  return notes;
}

}  // namespace snell
