// The derived oracle's cost beside the hand-written one: Listing 14.1's
// vertex stage over the sphere scene, double, float and fp32 intervals
// together, as a case evaluates it. The derived program is lowered once
// (as a case would), outside the timed loop; lowering is timed on its own.
// The reference image drawn from the listing's own text (fragment stage in
// double per pixel) beside referenceImageOfSphere (oracle_bench.cpp).
// Run: build/bench/snell_bench --benchmark_filter='Fresnel14_1|ImageOfSphere'
// --benchmark_repetitions=5
//        --benchmark_report_aggregates_only
#include <benchmark/benchmark.h>

#include <fstream>
#include <sstream>

#include "derived/derived_drawing.h"
#include "derived/derived_vertex_oracle.h"
#include "fresnel_inputs.h"
#include "oracle/reference/reference_image.h"
#include "oracle/vertex_oracle.h"

namespace snell {
namespace {

// A stage file of Listing 14.1, as published.
std::string fresnelStage(const char* file) {
  std::ifstream in(std::string(SNELL_SOURCE_ROOT) + "/shaders/orange-book/14.1-fresnel/" + file);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

struct Fresnel14_1 : FresnelInputs {
  derived::ShaderSource source{"fresnel.vert", fresnelStage("fresnel.vert"),
                               derived::Stage::Vertex};
  OracleInput input(PrecisionRules rules) const {
    return {uniforms, constants, attributes, scene.vertexCount, rules};
  }
};

void evaluate(benchmark::State& state, const VertexOracle& oracle, const Fresnel14_1& in) {
  const auto rules = static_cast<PrecisionRules>(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(oracle.evaluate(in.input(rules)));
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(in.scene.vertexCount));
  state.SetLabel(precisionRulesName(rules));
}

void handWrittenFresnel14_1(benchmark::State& state) {
  const Fresnel14_1 in;
  evaluate(state, *makeVertexOracle("orange_book_fresnel"), in);
}
BENCHMARK(handWrittenFresnel14_1)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

void derivedFresnel14_1(benchmark::State& state) {
  const Fresnel14_1 in;
  const auto oracle = derived::makeDerivedVertexOracle(
      in.source, makeVertexOracle("orange_book_fresnel")->outputs());
  evaluate(state, *oracle, in);
}
BENCHMARK(derivedFresnel14_1)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

void lowerFresnel14_1(benchmark::State& state) {
  const Fresnel14_1 in;
  for (auto _ : state) benchmark::DoNotOptimize(derived::lowerShader(in.source));
}
BENCHMARK(lowerFresnel14_1)->Unit(benchmark::kMicrosecond);

void derivedReferenceImageOfSphere(benchmark::State& state) {
  const Fresnel14_1 in;
  const auto vertex = derived::makeDerivedDrawingVertexOracle(in.source);
  const auto fragment = derived::makeDerivedFragmentOracle(
      {"fresnel.frag", fresnelStage("fresnel.frag"), derived::Stage::Fragment});
  for (auto _ : state) {
    benchmark::DoNotOptimize(
        renderReferenceImage(in.referenceInput("derived", vertex.get(), fragment.get())));
  }
  state.SetItemsProcessed(state.iterations() * in.scene.width * in.scene.height);
}
BENCHMARK(derivedReferenceImageOfSphere)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace snell
