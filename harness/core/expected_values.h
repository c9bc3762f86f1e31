#pragma once
// What an oracle says a captured output may be, as plain values: the exact
// value, the strict fp32 value and the interval the precision rules allow
// per component, with the ways a branch may go. The oracle computes them;
// compare/ holds read-backs against them without knowing any oracle type.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace snell {

// One way a sample's undecidable branches may go (oracle/branch_paths.h):
// a value per component along that path.
struct OracleAlternative {
  std::vector<double> reference;  // the listing in double, following the path
  std::vector<double> lo, hi;     // the fp32 results the spec allows on it
  std::vector<std::uint8_t> undefined;
};

struct SampleAlternatives {
  std::size_t sample = 0;
  std::vector<OracleAlternative> ways;  // two or more, distinct
};

struct OracleVarying {
  std::string name;
  int components = 1;
  // All four vectors hold vertexCount * components entries, vertex-major.
  std::vector<double> reference;  // the listing evaluated in double
  std::vector<float> strict;      // the listing evaluated in float
  std::vector<double> lo, hi;     // the fp32 results the spec allows (the hull of the ways)
  // 1 where the spec leaves the component undefined (pow of a negative
  // base, NaN, ...): such samples are reported as non-portable, not gated.
  std::vector<std::uint8_t> undefined;
  // Samples where a branch may go either way, in ascending sample order: a
  // read-back vector passes only when every component fits one way.
  std::vector<SampleAlternatives> alternatives;
  // Samples with more than kMaxBranchPaths ways, checked against the hull.
  std::size_t mergedToHull = 0;
};

}  // namespace snell
