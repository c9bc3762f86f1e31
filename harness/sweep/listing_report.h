#pragma once
// The listings' part of a sweep's JSON and terminal table: every break,
// grouped by listing, backend, output, frame, input, kind and class with
// its angle and eta ranges; the listings not swept and why; each
// listing's own total internal reflection boundary against the closed form.
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "sweep/listing_sweep.h"

namespace snell::sweep {

struct ListingBreakGroup {
  std::string listing, backend, output, frame, input, kind, cls;
  std::size_t count = 0;
  double angleMin = 0, angleMax = 0, etaMin = 0, etaMax = 0;
};

std::vector<ListingBreakGroup> groupListingBreaks(const std::vector<ListingBreak>& breaks);

nlohmann::json listingSweepJson(const ListingSweepResult& result);

void printListingTable(const ListingSweepResult& result, std::FILE* out);

}  // namespace snell::sweep
