#pragma once
// A `snell sweep --out` folder read for the HTML report: each listing's
// breaks summarised per backend and class (count, kinds, the first points,
// the worst), the maps drawn for it, and the sweep's own charts. Only the
// JSON and the chart files are read, so the report needs no sweep code.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace snell {

struct SweepPointText {
  std::string text;  // "41.8 deg, eta 1.5: (0, 0, 0): detail"
};

struct SweepGroup {
  std::string backend, cls;
  std::size_t count = 0;
  std::string kinds;  // "3 zero_where_physics_refracts, 1 nan"
  std::vector<SweepPointText> first;
  SweepPointText worst;
};

struct SweepChart {
  std::string caption;
  std::filesystem::path png;
};

struct ListingFindings {
  bool covered = false;
  std::string why;  // when not covered
  std::vector<SweepGroup> groups;
  std::vector<SweepChart> charts;
};

struct SweepFindings {
  std::filesystem::path dir;
  std::vector<std::string> swept;
  std::map<std::string, std::string> notSwept;  // listing -> why
  std::map<std::string, std::vector<SweepGroup>> groups;
  std::vector<SweepChart> charts;  // the sweep's maps and error charts
};

// Reads DIR/sweep.json; a missing or malformed file (or one written
// without listings) throws UsageError naming the file and what to do.
SweepFindings readSweepFindings(const std::filesystem::path& dir);

ListingFindings findingsFor(const SweepFindings& findings, const std::string& listing);

// The file stem of a listing's map for one backend, shared by the sweep
// that draws it and the report that embeds it.
std::string listingMapStem(const std::string& listing, const std::string& backend);

}  // namespace snell
