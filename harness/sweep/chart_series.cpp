#include "sweep/chart_series.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <set>
#include <tuple>

namespace snell::sweep {

std::map<std::string, std::string> mergedMarks(const std::vector<MapMark>& marks) {
  // (x, y, what) -> who; the grid gives every backend the same x and y bits.
  std::map<std::tuple<double, double, std::string>, std::set<std::string>> byPoint;
  for (const MapMark& m : marks) byPoint[{m.x, m.y, m.what}].insert(m.who);
  std::map<std::string, std::string> series;
  for (const auto& [point, who] : byPoint) {
    const auto& [x, y, what] = point;
    series[fmt::format("{}: {}", fmt::join(who, ", "), what)] +=
        fmt::format("{:.10g} {:.10g}\n", x, y);
  }
  return series;
}

std::vector<std::optional<std::size_t>> sameAsEarlier(const std::vector<std::string>& rows) {
  std::vector<std::optional<std::size_t>> same(rows.size());
  for (std::size_t k = 0; k < rows.size(); ++k)
    for (std::size_t j = 0; j < k && !same[k]; ++j)
      if (!rows[k].empty() && rows[k] == rows[j]) same[k] = j;
  return same;
}

}  // namespace snell::sweep
