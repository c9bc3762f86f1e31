// What the oracle costs per case: Listing 14.1's vertex oracle (double,
// float and fp32 intervals together) over the sphere scene, and the CPU
// reference image of the same scene.
// Run: build/bench/snell_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only
#include <benchmark/benchmark.h>

#include "fresnel_inputs.h"
#include "oracle/reference/reference_image.h"
#include "oracle/vertex_oracle.h"

namespace snell {
namespace {

void vertexOracleOnSphere(benchmark::State& state) {
  const FresnelInputs in;
  const auto oracle = makeVertexOracle("orange_book_fresnel");
  for (auto _ : state)
    benchmark::DoNotOptimize(
        oracle->evaluate({in.uniforms, in.constants, in.attributes, in.scene.vertexCount}));
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(in.scene.vertexCount));
}
BENCHMARK(vertexOracleOnSphere)->Unit(benchmark::kMillisecond);

void referenceImageOfSphere(benchmark::State& state) {
  const FresnelInputs in;
  for (auto _ : state) {
    benchmark::DoNotOptimize(renderReferenceImage(in.referenceInput("orange_book_fresnel")));
  }
  state.SetItemsProcessed(state.iterations() * in.scene.width * in.scene.height);
}
BENCHMARK(referenceImageOfSphere)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace snell
