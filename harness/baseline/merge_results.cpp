#include "baseline/merge_results.h"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <set>

#include "core/errors.h"

namespace snell {

std::vector<CaseResult> mergeResults(const std::vector<ResultsFile>& files,
                                     const std::vector<Case>& catalog) {
  std::map<std::string, std::size_t> caseOrder;
  for (const Case& c : catalog) caseOrder.emplace(c.id, caseOrder.size());
  std::map<std::pair<std::string, std::size_t>, std::pair<const CaseResult*, const std::string*>>
      merged;
  for (const ResultsFile& file : files)
    for (const CaseResult& r : file.results) {
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
  std::vector<CaseResult> results;
  for (const auto& [key, value] : merged) results.push_back(*value.first);
  return results;
}

}  // namespace snell
