#pragma once
// Inputs for the adversarial machine's checks: random ones, and the edges
// where a sloppy interval would fail first (near the critical angle, at
// grazing incidence, eta within a few percent of 1, head on, denormals,
// huge values); and the catalog listings bound to their scenes.
#include <cstdint>
#include <vector>

#include "adversary/adversary_check.h"

namespace snell::adversary {

class Rng {
 public:
  explicit Rng(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next();
  double uniform(double lo, double hi);  // [lo, hi)
  int below(int n);
  bool percent(int p) { return below(100) < p; }

 private:
  std::uint64_t state_;
};

// Inputs for one call of the formula, edges about half the time.
std::vector<float> formulaInputs(Formula f, Rng& rng);

// Every catalog manifest's listing bound to the scene of its first case
// (one per oracle and set of constants).
const std::vector<ListingInputs>& catalogListings();

// Every catalog manifest's vertex and fragment captures, as the derived
// oracle computes them (derived/manifest_requests.h), bound to the scene of
// its first case (listings published as not compiling left out).
const std::vector<DerivedListingInputs>& derivedCatalogListings();

// `count` vertices of `all`, drawn at random; some of them with their
// attributes replaced by edge directions, with denormals and huge or tiny
// scales unless `unitEdges` (the edge directions stay unit vectors).
ListingInputs sampleVertices(const ListingInputs& all, std::size_t count, Rng& rng,
                             bool unitEdges = false);

}  // namespace snell::adversary
