#pragma once
// The derived oracle held against a hand-written one over the same
// samples: the derived interval must hold the hand-written exact value
// everywhere, the two exact values must agree, and the widths are reported
// (derived / hand-written).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "core/expected_values.h"
#include "oracle/precision_rules.h"

namespace snell::test {

// The width bounds (derived / hand-written). Both oracles run the same
// built-ins over the same operations in the same order, so wherever every
// condition is decided the intervals are the same: the median ratio is 1.
// Where a condition may go either way both keep the ways apart and report
// their hull, so the ratio stays 1 there too, unless the paths exceed
// kMaxBranchPaths and a sample falls back to the hull taken at each branch
// and carried through the operations after it (a refract() whose result
// then goes through TextureMatrix * vec4(R, 1)). A hull carried through a
// row of a 4 x 4 matrix is at most four terms each as wide as the widest
// way, hence 4 for the worst sample.
constexpr double kWorstWidthRatio = 4.0;

// How far apart two exact values may be: a few double ulps, for an
// operation that the two evaluate in a different (but equally exact) order.
constexpr double kExactUlps = 4.0;

struct Comparison {
  std::size_t components = 0;
  std::size_t outside = 0;          // hand-written exact value not in the derived interval
  std::size_t exactMismatch = 0;    // exact values more than kExactUlps apart
  std::size_t skipped = 0;          // undefined in either oracle
  std::vector<double> widthRatios;  // where both widths are finite and the hand-written's > 0
  std::string firstOutside;
  // Samples whose branches may go either way, kept apart as alternatives.
  std::size_t handWays = 0, derivedWays = 0;
  std::size_t waySamplesDiffer = 0;
};

inline bool withinUlps(double a, double b, double ulps) {
  if (std::isnan(a) || std::isnan(b)) return std::isnan(a) && std::isnan(b);
  const double scale = std::max(std::fabs(a), std::fabs(b));
  const double ulp = std::nextafter(scale, INFINITY) - scale;
  return std::fabs(a - b) <= ulps * ulp;
}

inline Comparison compare(const std::vector<OracleVarying>& hand,
                          const std::vector<OracleVarying>& derived) {
  Comparison result;
  for (const OracleVarying& h : hand) {
    auto d = std::find_if(derived.begin(), derived.end(),
                          [&](const OracleVarying& v) { return v.name == h.name; });
    if (d == derived.end()) {
      ADD_FAILURE() << "the derived oracle has no output " << h.name;
      continue;
    }
    EXPECT_EQ(d->components, h.components) << h.name;
    result.handWays += h.alternatives.size();
    result.derivedWays += d->alternatives.size();
    if (h.alternatives.size() != d->alternatives.size()) {
      ++result.waySamplesDiffer;
    } else {
      for (std::size_t k = 0; k < h.alternatives.size(); ++k)
        if (h.alternatives[k].sample != d->alternatives[k].sample ||
            h.alternatives[k].ways.size() != d->alternatives[k].ways.size())
          ++result.waySamplesDiffer;
    }
    for (std::size_t i = 0; i < h.reference.size(); ++i) {
      ++result.components;
      if (h.undefined[i] || d->undefined[i]) {
        ++result.skipped;
        continue;
      }
      const double exact = h.reference[i];
      if (!(d->lo[i] <= exact && exact <= d->hi[i])) {
        if (result.outside++ == 0)
          result.firstOutside = h.name + "[" + std::to_string(i) + "]: " + std::to_string(exact) +
                                " not in [" + std::to_string(d->lo[i]) + ", " +
                                std::to_string(d->hi[i]) + "]";
      }
      if (!withinUlps(d->reference[i], exact, kExactUlps)) ++result.exactMismatch;
      const double handWidth = h.hi[i] - h.lo[i];
      const double derivedWidth = d->hi[i] - d->lo[i];
      if (std::isfinite(handWidth) && std::isfinite(derivedWidth) && handWidth > 0)
        result.widthRatios.push_back(derivedWidth / handWidth);
    }
  }
  return result;
}

inline double median(std::vector<double> values) {
  if (values.empty()) return 0;
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

// Every check above on one listing's outputs, with the widths printed.
inline void expectAgreement(const std::string& label, PrecisionRules rules,
                            const std::vector<OracleVarying>& hand,
                            const std::vector<OracleVarying>& derived) {
  const Comparison c = compare(hand, derived);
  ASSERT_GT(c.components, 0u);
  EXPECT_EQ(c.outside, 0u) << c.firstOutside;
  EXPECT_EQ(c.exactMismatch, 0u);
  // Both keep the same samples' ways apart, with as many ways.
  EXPECT_EQ(c.waySamplesDiffer, 0u) << c.handWays << " vs " << c.derivedWays;
  // Undefined samples are not compared; they must stay rare.
  EXPECT_LT(c.skipped * 10, c.components);
  ASSERT_FALSE(c.widthRatios.empty());
  const double worst = *std::max_element(c.widthRatios.begin(), c.widthRatios.end());
  std::printf(
      "[ widths   ] %-24s %-6s derived/hand-written width: median %.3f, worst %.3f "
      "(%zu components, %zu undefined, %zu samples with ways apart)\n",
      label.c_str(), precisionRulesName(rules), median(c.widthRatios), worst, c.components,
      c.skipped, c.derivedWays);
  EXPECT_LE(worst, kWorstWidthRatio);
  EXPECT_NEAR(median(c.widthRatios), 1.0, 1e-12);
}

}  // namespace snell::test
