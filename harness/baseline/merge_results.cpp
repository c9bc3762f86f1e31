#include "baseline/merge_results.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <map>
#include <set>

#include "baseline/driver_build.h"
#include "baseline/shard.h"
#include "core/errors.h"
#include "core/listing_digest.h"

namespace snell {
namespace {

// A run's shards, as the records name them: (the run's selection, shard
// count N) -> the shards I given, and the cases each shard of the run holds
// where its records say. Records written before records named their run
// (no shard_of) count for every run of their N.
struct ShardsOfRun {
  std::set<std::size_t> given;
  std::vector<std::size_t> cases;  // per shard; empty where no record says
};
using ShardsOfRuns = std::map<std::pair<std::string, std::size_t>, ShardsOfRun>;

ShardsOfRuns shardsOfRuns(const std::vector<ResultsFile>& files) {
  ShardsOfRuns seen;
  std::map<std::size_t, std::set<std::size_t>> unnamed;  // N -> I
  for (const ResultsFile& file : files)
    for (const CaseResult& r : file.results) {
      if (r.shard.empty()) continue;
      const Shard shard = parseShard(r.shard);
      if (r.shardOf.empty()) {
        unnamed[shard.count].insert(shard.index);
        continue;
      }
      ShardsOfRun& run = seen[{r.shardOf, shard.count}];
      run.given.insert(shard.index);
      // Runners may count apart (a skip list a day older, a backend that
      // did not come up): a shard had cases if any record says so.
      if (r.shardCases.size() == shard.count) {
        run.cases.resize(shard.count, 0);
        for (std::size_t i = 0; i < shard.count; ++i)
          run.cases[i] = std::max(run.cases[i], r.shardCases[i]);
      }
    }
  for (const auto& [count, indices] : unnamed) {
    bool joined = false;
    for (auto& [run, shards] : seen)
      if (run.second == count) {
        shards.given.insert(indices.begin(), indices.end());
        joined = true;
      }
    if (!joined) seen[{"", count}].given = indices;
  }
  return seen;
}

// Records say which shard of how many ran them, and of which run (its
// --filter and --backend): a merge that lacks one of a run's shards would be
// a run with cases missing and no word of it, also where another run's
// shard (another filter or backend list) stands in its place. Shards are
// counted per run over all files, not per backend: a shard may hold no
// record of a backend (its cases skipped there, or the backend not up on
// that runner), and each backend may be a run of its own, sharded apart.
// Records also say how many cases each shard of their run holds: a shard
// with none needs no file, and one with cases is missing whatever else is
// given. Where no record says (records written before they counted), a
// file with no results may stand for any one shard. Records of a whole run
// say nothing and are not counted.
void requireEveryShard(const std::vector<ResultsFile>& files) {
  const std::size_t emptyFiles = static_cast<std::size_t>(std::count_if(
      files.begin(), files.end(), [](const ResultsFile& f) { return f.results.empty(); }));
  // Every run that lacks shards is named: where a shard of another run was
  // given in place of one, both runs are. An empty file is one shard of one
  // run: it stands for one missing shard, of unknown size, in all.
  std::vector<std::string> lacking, lackingWithCases;
  std::size_t unknownShards = 0;
  for (const auto& [run, shards] : shardsOfRuns(files)) {
    const auto& [selection, count] = run;
    std::vector<std::string> missing, withCases;
    for (std::size_t i = 1; i <= count; ++i) {
      if (shards.given.contains(i)) continue;
      if (shards.cases.empty()) {
        missing.push_back(fmt::format("{}/{}", i, count));
        ++unknownShards;
      } else if (shards.cases[i - 1] > 0) {
        withCases.push_back(fmt::format("{}/{} ({} case{})", i, count, shards.cases[i - 1],
                                        shards.cases[i - 1] == 1 ? "" : "s"));
      }
    }
    const std::string ofTheRun =
        selection.empty() ? std::string() : fmt::format(" of the run of {}", selection);
    if (!missing.empty())
      lacking.push_back(fmt::format("shard {}{}", fmt::join(missing, ", "), ofTheRun));
    if (!withCases.empty())
      lackingWithCases.push_back(fmt::format("shard {}{}", fmt::join(withCases, ", "), ofTheRun));
  }
  if (!lackingWithCases.empty())
    throw UsageError(fmt::format(
        "no results of {}: merge every shard's results file, or run the missing shard with the "
        "same --filter, --backend and --expectations{}",
        fmt::join(lackingWithCases, "; nor of "),
        emptyFiles == 0 ? std::string()
                        : " (an empty file stands only for a shard with no cases to give)"));
  if (unknownShards > emptyFiles)
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
  std::map<const Manifest*, std::string> digestOf;  // of the catalog's listings, once each
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
      // A shard run on another catalog (an edited listing, another
      // commit's) is not a shard of this run, whose other cases ran on
      // these listings.
      if (const Manifest* listing = catalog[order->second].manifest;
          listing && !r.listingDigest.empty()) {
        auto [digest, fresh] = digestOf.try_emplace(listing);
        if (fresh) digest->second = listingDigest(*listing);
        if (r.listingDigest == kListingEditedDuringRun)
          throw UsageError(fmt::format(
              "{}: ran {} on {} while {} was being edited, so which text it ran is unknown: run "
              "that shard again",
              file.path, r.caseId, r.backend, listing->path.string()));
        if (digest->second != r.listingDigest)
          throw UsageError(fmt::format(
              "{}: ran {} on {} from another text of its listing than {} and its shader files "
              "(a shard of another commit, or a listing edited since): merge the shards of one "
              "run, with --shaders the catalog they ran",
              file.path, r.caseId, r.backend, listing->path.string()));
      }
      const auto [it, added] =
          merged.emplace(std::pair(r.backend, order->second), std::pair(&r, &file.path));
      if (!added) {
        // Shards of two runs (another --filter or --backend list, or
        // another shard count) overlap where their selections do: that is
        // the mistake to name, not the overlap.
        const CaseResult& other = *it->second.first;
        if (!r.shardOf.empty() && !other.shardOf.empty() && !r.shard.empty() &&
            !other.shard.empty() &&
            (r.shardOf != other.shardOf ||
             parseShard(r.shard).count != parseShard(other.shard).count))
          throw UsageError(fmt::format(
              "{} holds shard {} of the run of {}, and {} shard {} of the run of {}: a merge "
              "joins the shards of one run (these two both hold {} on {}); merge each run's "
              "shards apart, or run the missing shards with the same --filter, --backend and "
              "--shard count",
              *it->second.second, other.shard, other.shardOf, file.path, r.shard, r.shardOf,
              r.caseId, r.backend));
        throw UsageError(
            fmt::format("{} and {} both hold {} on {}: shards must not overlap; "
                        "merge the results of one run's shards only",
                        *it->second.second, file.path, r.caseId, r.backend));
      }
    }
  requireEveryShard(files);
  std::vector<CaseResult> results;
  for (const auto& [key, value] : merged) {
    results.push_back(*value.first);
    results.back().shard.clear();  // the merge is the whole run
    results.back().shardOf.clear();
    results.back().shardCases.clear();
  }
  return results;
}

}  // namespace snell
