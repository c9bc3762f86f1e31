// What the oracle costs per case: Listing 14.1's vertex oracle (double,
// float and fp32 intervals together) over the sphere scene, the CPU
// reference image of the same scene, and reflect() and refract() alone
// (the built-ins every listing calls) in double, in float and as fp32
// intervals under each API's precision rules.
// Run: build/bench/snell_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <type_traits>
#include <vector>

#include "fresnel_inputs.h"
#include "oracle/glsl/glsl.h"
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

// Unit incident and normal vectors as a shader gets them (fp32), in a fixed
// pseudo-random sequence, with incidence angles over the whole range (near
// grazing, and near the critical angle for eta = 0.66, included), in the
// number type T: double (the reference's exact values), float (what an fp32
// evaluation gives) or Interval (what the spec allows).
template <class T>
T fromFloat(float x) {
  if constexpr (std::is_same_v<T, Interval>)
    return Interval::point(x);
  else
    return static_cast<T>(x);
}

template <class T>
struct UnitPairs {
  std::vector<glsl::vec3<T>> incident;
  std::vector<glsl::vec3<T>> normal;
  explicit UnitPairs(std::size_t count) {
    std::mt19937 rng(13);
    std::normal_distribution<double> gauss;
    const auto unit = [&] {
      double x = gauss(rng), y = gauss(rng), z = gauss(rng);
      const double n = std::sqrt(x * x + y * y + z * z);
      return glsl::vec3<T>(fromFloat<T>(static_cast<float>(x / n)),
                           fromFloat<T>(static_cast<float>(y / n)),
                           fromFloat<T>(static_cast<float>(z / n)));
    };
    for (std::size_t i = 0; i < count; ++i) {
      incident.push_back(unit());
      normal.push_back(unit());
    }
  }
};

// Interval benchmarks take the precision rules as their argument: 0 GLSL, 1 Vulkan.
PrecisionRules rulesOf(const benchmark::State& state) {
  return state.range(0) == 0 ? PrecisionRules::Glsl : PrecisionRules::Vulkan;
}

template <class T>
void reflectIn(benchmark::State& state) {
  const UsePrecisionRules rules(rulesOf(state));
  const UnitPairs<T> pairs(1024);
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(glsl::reflect(pairs.incident[i], pairs.normal[i]));
    i = (i + 1) % pairs.incident.size();
  }
  state.SetItemsProcessed(state.iterations());
  if constexpr (std::is_same_v<T, Interval>) state.SetLabel(precisionRulesName(rulesOf(state)));
}
BENCHMARK(reflectIn<double>)->Name("reflectDouble")->Arg(0);
BENCHMARK(reflectIn<float>)->Name("reflectFloat")->Arg(0);
BENCHMARK(reflectIn<Interval>)->Name("reflectInterval")->Arg(0)->Arg(1);

template <class T>
void refractIn(benchmark::State& state) {
  const UsePrecisionRules rules(rulesOf(state));
  const UnitPairs<T> pairs(1024);
  T eta;
  if constexpr (std::is_same_v<T, Interval>)
    eta = Interval::literal(0.66);
  else
    eta = static_cast<T>(0.66f);
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(glsl::refract(pairs.incident[i], pairs.normal[i], eta));
    i = (i + 1) % pairs.incident.size();
  }
  state.SetItemsProcessed(state.iterations());
  if constexpr (std::is_same_v<T, Interval>) state.SetLabel(precisionRulesName(rulesOf(state)));
}
BENCHMARK(refractIn<double>)->Name("refractDouble")->Arg(0);
BENCHMARK(refractIn<float>)->Name("refractFloat")->Arg(0);
BENCHMARK(refractIn<Interval>)->Name("refractInterval")->Arg(0)->Arg(1);

}  // namespace
}  // namespace snell
