// What comparing read-back vectors against the oracle's intervals costs
// (the `compare` phase of a run): checkVarying over 3-component vectors
// whose results are exact, inside their interval or, rarely, outside it,
// as a driver's are. Items are components.
// Run: build/bench/snell_bench --benchmark_filter=checkVarying
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

#include "compare/vector_check.h"

namespace snell {
namespace {

struct ComparedVarying {
  OracleVarying expected;
  CapturedVarying observed;
};

ComparedVarying varyingWithDriverLikeResults(std::size_t samples, bool withAlternatives) {
  constexpr int kComponents = 3;
  ComparedVarying v;
  v.expected.name = v.observed.name = "R";
  v.expected.components = v.observed.components = kComponents;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  std::uniform_int_distribution<int> outcome(0, 99);
  for (std::size_t k = 0; k < samples * kComponents; ++k) {
    const double reference = value(random);
    const auto nearest = static_cast<float>(reference);
    const double ulp = std::nextafter(nearest, 2.0f) - nearest;
    v.expected.reference.push_back(reference);
    v.expected.strict.push_back(nearest);
    v.expected.lo.push_back(nearest - 2 * ulp);
    v.expected.hi.push_back(nearest + 2 * ulp);
    v.expected.undefined.push_back(0);
    // Half exact, half within the interval, one in a hundred outside.
    const int roll = outcome(random);
    const double off = roll == 0 ? 5 * ulp : roll < 50 ? 0.0 : ulp;
    v.observed.data.push_back(static_cast<float>(nearest + off));
  }
  if (withAlternatives)
    for (std::size_t s = 0; s < samples; s += 10) {
      SampleAlternatives sample;
      sample.sample = s;
      for (int way = 0; way < 2; ++way) {
        OracleAlternative a;
        for (int c = 0; c < kComponents; ++c) {
          const std::size_t at = s * kComponents + static_cast<std::size_t>(c);
          a.reference.push_back(v.expected.reference[at]);
          a.lo.push_back(v.expected.lo[at]);
          a.hi.push_back(v.expected.hi[at]);
          a.undefined.push_back(0);
        }
        sample.ways.push_back(std::move(a));
      }
      v.expected.alternatives.push_back(std::move(sample));
    }
  return v;
}

// range(0): 1 gives every tenth sample two ways to go.
void checkVaryingOnDriverResults(benchmark::State& state) {
  const ComparedVarying v = varyingWithDriverLikeResults(200'000, state.range(0) != 0);
  for (auto _ : state) benchmark::DoNotOptimize(checkVarying(v.expected, v.observed));
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(v.observed.data.size()));
}
BENCHMARK(checkVaryingOnDriverResults)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace snell
