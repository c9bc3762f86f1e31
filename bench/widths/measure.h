#pragma once
// One sample's evidence and the per-row statistics: interval widths in ULPs
// of the result (snell's oracle and the dEQP-style interval) and how many
// conforming values fall outside each ("spec-window escapes").
#include <cstddef>
#include <string>
#include <vector>

#include "oracle/precision_rules.h"
#include "widths/conforming_sampler.h"
#include "widths/deqp_interval.h"
#include "widths/snell_intervals.h"

namespace snell::widths {

struct SampleRecord {
  std::vector<double> reference;               // the expression in double
  std::vector<DeqpValue> deqp;                 // the dEQP-style box
  SnellSample snell;                           // snell's ways
  std::vector<std::vector<float>> conforming;  // values a conforming machine returned
  std::string input;                           // how to reproduce the sample
};

// Whether every component that the box constrains holds the value.
bool boxAllows(const std::vector<DeqpValue>& box, const std::vector<float>& vector);

struct RowStats {
  std::string row;    // "refract / near-critical", "orange_book_fresnel (14.1-fresnel) / Refract"
  std::string rules;  // "glsl" / "vulkan"
  std::size_t samples = 0;
  std::size_t measured = 0;   // components whose widths were compared
  std::size_t split = 0;      // samples where snell keeps two or more ways (not in the widths)
  std::size_t undefined = 0;  // samples with a component either interval leaves open
  std::size_t zero = 0;       // components both hold at exactly 0 (not in the widths)
  double snellMedian = 0, snellMax = 0, deqpMedian = 0, deqpMax = 0;  // ULPs of the result
  std::size_t conforming = 0;  // conforming vectors held against both
  std::size_t snellEscapes = 0, deqpEscapes = 0;
  std::string snellEscape, deqpEscape;  // the first escape of each, reproducible
  // The component where snell's width exceeds the dEQP-style one the most
  // (ratio of the widths), reproducible.
  double widestRatio = 0;
  std::string widest;
};

class RowAccumulator {
 public:
  RowAccumulator(std::string row, PrecisionRules rules);
  void add(const SampleRecord& record);
  RowStats finish() const;

 private:
  RowStats stats_;
  std::vector<double> snellWidths_, deqpWidths_;
};

// The machine's choices for one input: every rounding direction with and
// without fusion, then random per-operation rounding with flushed denormals.
std::vector<SamplerChoices> conformingChoices(std::uint64_t seed, std::size_t count);

SampleRecord builtinRecord(const std::string& fn, const std::vector<float>& I,
                           const std::vector<float>& N, float eta, PrecisionRules rules,
                           std::size_t conformingPerInput, std::uint64_t seed);

// [output][vertex]
std::vector<std::vector<SampleRecord>> listingRecords(const std::string& oracle,
                                                      const ListingBindings& bindings,
                                                      PrecisionRules rules,
                                                      std::size_t conformingPerInput,
                                                      std::uint64_t seed);

}  // namespace snell::widths
