#include "compare/vector_check.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <utility>
#include <vector>

#include "compare/slack.h"

namespace snell {

namespace {

// One way a sample may go: its components' exact values and intervals.
struct Way {
  const double* reference;
  const double* lo;
  const double* hi;
  const std::uint8_t* undefined;
};

double componentSlack(const Way& way, int c, float observed) {
  if (way.undefined[c]) return 0.0;
  return slack(observed, way.reference[c], way.lo[c], way.hi[c]);
}

double worstComponentSlack(const Way& way, int components, const float* observed) {
  double worst = 0.0;
  for (int c = 0; c < components; ++c) worst = std::max(worst, componentSlack(way, c, observed[c]));
  return worst;
}

bool fits(const Way& way, int components, const float* observed) {
  for (int c = 0; c < components; ++c)
    if (!way.undefined[c] && !withinSpec(observed[c], way.lo[c], way.hi[c])) return false;
  return true;
}

bool sameFailure(const ComponentFailure& a, const ComponentFailure& b) {
  return a.component == b.component && a.observed == b.observed && a.lo == b.lo && a.hi == b.hi &&
         a.reference == b.reference;
}

void keepIfAmongWorst(std::vector<ComponentFailure>& kept, const ComponentFailure& failure) {
  for (const ComponentFailure& k : kept)
    if (sameFailure(k, failure)) return;
  if (kept.size() < VaryingCheck::kFailuresKept) {
    kept.push_back(failure);
    return;
  }
  const auto mildest = std::min_element(
      kept.begin(), kept.end(),
      [](const ComponentFailure& a, const ComponentFailure& b) { return a.slack < b.slack; });
  if (failure.slack > mildest->slack) *mildest = failure;
}

}  // namespace

std::size_t slackBin(double slack) {
  // The first bin whose upper bound holds the slack is the number of bounds
  // below it (they ascend); NaN is above every bound. Counted without a
  // branch: slacks come in no order a predictor could learn.
  std::size_t bin = 0;
  for (std::size_t k = 0; k + 1 < kSlackBinUpper.size(); ++k)
    bin += static_cast<std::size_t>(!(slack <= kSlackBinUpper[k]));
  return bin;
}

VaryingCheck checkVarying(const OracleVarying& expected, const CapturedVarying& observed) {
  if (expected.name != observed.name || expected.components != observed.components ||
      expected.reference.size() != observed.data.size() ||
      expected.lo.size() != observed.data.size() || expected.hi.size() != observed.data.size() ||
      expected.undefined.size() != observed.data.size() || expected.components < 1)
    throw std::invalid_argument(fmt::format(
        "oracle output {} ({} x {}) does not match captured {} ({} values)", expected.name,
        expected.components, expected.reference.size(), observed.name, observed.data.size()));
  VaryingCheck check;
  check.name = expected.name;
  const int components = expected.components;
  const std::size_t samples = observed.data.size() / static_cast<std::size_t>(components);
  auto alternative = expected.alternatives.begin();
  // The ways of a sample with alternatives; reused, so a sample allocates
  // nothing.
  std::vector<Way> ways;
  for (std::size_t sample = 0; sample < samples; ++sample) {
    const std::size_t base = sample * static_cast<std::size_t>(components);
    const float* values = &observed.data[base];
    while (alternative != expected.alternatives.end() && alternative->sample < sample)
      ++alternative;
    const bool hasAlternatives =
        alternative != expected.alternatives.end() && alternative->sample == sample;
    // Without alternatives, the one interval; with them, the way it fits
    // best: the smallest worst slack among those it fits whole, else among
    // all.
    const Way single{&expected.reference[base], &expected.lo[base], &expected.hi[base],
                     &expected.undefined[base]};
    const Way* best = &single;
    bool fitsAWay = false;
    int wayCount = 1;
    if (hasAlternatives) {
      ++check.withAlternatives;
      ways.clear();
      for (const OracleAlternative& a : alternative->ways)
        ways.push_back({a.reference.data(), a.lo.data(), a.hi.data(), a.undefined.data()});
      wayCount = static_cast<int>(ways.size());
      best = &ways[0];
      double bestSlack = worstComponentSlack(*best, components, values);
      fitsAWay = fits(*best, components, values);
      for (std::size_t w = 1; w < ways.size(); ++w) {
        const double s = worstComponentSlack(ways[w], components, values);
        const bool f = fits(ways[w], components, values);
        if ((f && !fitsAWay) || (f == fitsAWay && s < bestSlack)) {
          best = &ways[w];
          bestSlack = s;
          fitsAWay = f;
        }
      }
    }
    for (int c = 0; c < components; ++c) {
      if (best->undefined[c]) {
        ++check.undefined;
        continue;
      }
      ++check.checked;
      const double s = componentSlack(*best, c, values[c]);
      ++check.slackHistogram[slackBin(s)];
      if (s > check.worstSlack) {
        check.worstSlack = s;
        check.worstVertex = sample;
      }
      // A sample that fits a way whole passes; otherwise each component
      // outside the nearest way's interval fails.
      if (fitsAWay || withinSpec(values[c], best->lo[c], best->hi[c])) continue;
      ++check.failed;
      keepIfAmongWorst(check.worstFailures, {sample, c, values[c], best->reference[c], best->lo[c],
                                             best->hi[c], s, wayCount});
    }
  }
  // Worst first; equal slack in sample order, so the order is reproducible.
  std::sort(check.worstFailures.begin(), check.worstFailures.end(),
            [](const ComponentFailure& a, const ComponentFailure& b) {
              return a.slack != b.slack
                         ? a.slack > b.slack
                         : std::pair{a.vertex, a.component} < std::pair{b.vertex, b.component};
            });
  return check;
}

}  // namespace snell
