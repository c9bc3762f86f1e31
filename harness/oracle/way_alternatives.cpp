#include "oracle/way_alternatives.h"

#include <algorithm>
#include <utility>

namespace snell {

void addWayAlternatives(std::vector<OracleVarying>& varyings, std::size_t sample,
                        const std::vector<std::vector<Interval>>& ways,
                        const std::vector<std::vector<double>>& references) {
  std::size_t offset = 0;
  for (OracleVarying& varying : varyings) {
    const auto components = static_cast<std::size_t>(varying.components);
    SampleAlternatives alternatives{sample, {}};
    for (std::size_t w = 0; w < ways.size(); ++w) {
      OracleAlternative way;
      for (std::size_t c = 0; c < components; ++c) {
        const Interval& value = ways[w][offset + c];
        way.reference.push_back(references[w][offset + c]);
        way.lo.push_back(value.lo);
        way.hi.push_back(value.hi);
        way.undefined.push_back(value.undefined ? 1 : 0);
      }
      const auto same = [&](const OracleAlternative& other) {
        return other.lo == way.lo && other.hi == way.hi && other.undefined == way.undefined;
      };
      if (std::none_of(alternatives.ways.begin(), alternatives.ways.end(), same))
        alternatives.ways.push_back(std::move(way));
    }
    if (alternatives.ways.size() > 1) varying.alternatives.push_back(std::move(alternatives));
    offset += components;
  }
}

}  // namespace snell
