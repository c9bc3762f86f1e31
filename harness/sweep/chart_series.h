#pragma once
// How a sweep's chart series are formed where several of them would draw
// the same marks or lines: backends that break at the same point the same
// way, or two Fresnel methods that give the same curve.
#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace snell::sweep {

// One mark on a break map: who breaks (a backend or a method), what break
// it is (kind and class, as the legend shows it), and where.
struct MapMark {
  std::string who;
  std::string what;
  double x = 0;
  double y = 0;
};

// The map's series, legend title to data rows ("x y\n" each). A point
// where several break the same way is one mark of one series, titled by
// all of them ("gl, oracle, vk: what"); each draws its own mark only where
// the others do not. Drawn one series per backend, three backends that
// agree stacked three marks on every point of a dense grid, and the map
// could not be read.
std::map<std::string, std::string> mergedMarks(const std::vector<MapMark>& marks);

// For each curve (its data rows), the index of an earlier curve with the
// same rows, if any: such a curve lies exactly on the earlier one, and its
// legend says so.
std::vector<std::optional<std::size_t>> sameAsEarlier(const std::vector<std::string>& rows);

}  // namespace snell::sweep
