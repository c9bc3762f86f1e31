#pragma once
// Every catalog listing in the sweep: drawn at every sweep point (a vertex
// each) on every driver through the same capture path as `snell run`, at
// its own eta and at every eta of the grid, in the unit and the stretched
// frame, with the bad inputs; held against its hand-written oracle and
// against the geometry (listing_classify.h).
#include <filesystem>
#include <string>
#include <vector>

#include "oracle/precision_rules.h"
#include "sweep/listing_classify.h"
#include "sweep/listing_draw.h"

namespace snell::sweep {

// The draws, one line each, that the driver children read: written to
// ListingSweepOptions::outDir and removed when the sweep ends.
inline constexpr const char* kListingJobFile = "sweep-listing-draws.txt";

struct ListingSweepOptions {
  std::string executable;               // the snell binary (its `sweep --listing-worker`)
  std::vector<std::string> backends;    // drivers
  std::vector<PrecisionRules> rules;    // each driver's API rules, same order
  std::vector<std::string> driverArgs;  // --device, --gl-provider
  std::filesystem::path shadersDir;
  std::string filter;  // glob over listing ids; empty: all
  std::filesystem::path outDir;
  bool quick = false;
  double timeoutSeconds = 120;  // per draw
};

struct ListingNote {
  std::string listing;
  std::string note;
};

struct ListingSweepResult {
  std::vector<std::string> swept;
  std::vector<ListingNote> notSwept;  // and why
  std::vector<ListingNote> notes;     // swept, but with a limit (no eta to set, ...)
  std::size_t draws = 0, vertices = 0;
  std::vector<ListingBreak> breaks;
  std::vector<ListingCriticalAngle> criticalAngles;
  double wallSeconds = 0;
};

ListingSweepResult runListingSweep(const ListingSweepOptions& options);

// The draws of one listing: as published in the unit frame (with the bad
// inputs) and in the stretched frame, then every grid eta in the unit frame.
std::vector<DrawSpec> listingDraws(const Manifest& manifest, bool quick);

}  // namespace snell::sweep
