// `snell eval`'s pipeline on batches of a million built-in calls, without
// its text: the calls are made in memory, then each chunk is drawn on the
// driver (upload, draw, read back) on the calling thread while every other
// core runs the oracle's intervals, and then each driver vector is held
// against its intervals, on every core. The same functions and the same
// chunks as eval (runner/builtin_draw.h, evaluateBuiltin); what eval adds
// is reading JSON and writing its answers. `oracle_glsl` and
// `oracle_vulkan` rows run the oracle alone, on every core, under the rules
// gl and vk are judged by; `general_road` rows run it without the shorter
// road for exact inputs (oracle/point_builtins.h), the same bounds.
//
// build/bench/snell_pipeline_bench --benchmark_repetitions=3 --benchmark_report_aggregates_only
#include <benchmark/benchmark.h>

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "backends/backend.h"
#include "oracle/builtin_probe.h"
#include "runner/block_pool.h"
#include "runner/builtin_draw.h"
#include "runner/builtin_eval.h"
#include "scaling/refract_inputs.h"

namespace snell {
namespace {

constexpr std::size_t kBatch = 1'000'000;
constexpr std::size_t kBlockLines = 256;  // as eval's blocks
// The lines of `snell_refract_vectors 1e6 7`, which the README's
// measurements of eval on a million lines read.
constexpr unsigned long long kSeed = 7;

std::vector<BuiltinCall> makeCalls(const std::string& fn) {
  bench::RefractInputs inputs(kSeed);
  std::vector<BuiltinCall> calls(kBatch);
  for (BuiltinCall& call : calls) {
    const bench::RefractInput in = inputs.next();
    call.fn = fn;
    call.I.assign(in.I.begin(), in.I.end());
    call.N.assign(in.N.begin(), in.N.end());
    if (fn == "refract") call.eta = in.eta;
  }
  return calls;
}

// A driver per backend name, brought up once for the whole process (its
// start is not what is measured); null with the reason when it does not
// come up.
struct Driver {
  std::unique_ptr<Backend> backend;
  std::string whyNot;
};
Driver& driverNamed(const std::string& name) {
  // Never destroyed: a GL context torn down from a static destructor runs
  // after Mesa's own exit handlers and may crash inside libOSMesa.
  static auto* drivers = new std::map<std::string, Driver>;
  auto [at, added] = drivers->try_emplace(name);
  if (added) {
    try {
      at->second.backend = makeBackend(name, {});
    } catch (const std::exception& error) {
      at->second.whyNot = error.what();
    }
  }
  return at->second;
}

// `backendName` is a driver, judged by its API's rules, or
// `oracle:glsl` / `oracle:vulkan`, the oracle alone under those rules.
void pipeline(benchmark::State& state, const std::string& backendName, const std::string& fn,
              OracleRoad road = OracleRoad::Shortest) {
  Backend* backend = nullptr;
  PrecisionRules rules = PrecisionRules::Glsl;
  if (backendName == "oracle:glsl" || backendName == "oracle:vulkan") {
    rules = backendName == "oracle:glsl" ? PrecisionRules::Glsl : PrecisionRules::Vulkan;
  } else {
    Driver& driver = driverNamed(backendName);
    if (!driver.backend) {
      state.SkipWithError(("no " + backendName + " driver: " + driver.whyNot).c_str());
      return;
    }
    backend = driver.backend.get();
    rules = precisionRulesForApi(backend->driverInfo().api);
  }
  const std::vector<BuiltinCall> calls = makeCalls(fn);
  const std::size_t chunk = EvalOptions{}.chunkLines;
  BlockPool pool(defaultEvalThreads());
  std::vector<std::optional<BuiltinResult>> oracle(chunk);
  std::vector<std::vector<float>> driverVectors(chunk);
  std::vector<DrawnCall> drawn(chunk);
  std::atomic<std::size_t> outside{0};

  const auto runChunk = [&](std::size_t first, std::size_t count) {
    for (std::size_t k = 0; k < count; ++k) drawn[k] = {&calls[first + k], &driverVectors[k]};
    pool.run(
        count, kBlockLines,
        [&](std::size_t begin, std::size_t end) {
          for (std::size_t k = begin; k < end; ++k)
            oracle[k] = evaluateBuiltin(calls[first + k], rules, road);
        },
        [&] {
          if (backend) drawBuiltinCalls(std::span(drawn.data(), count), *backend);
        });
    if (!backend) return;
    pool.run(count, kBlockLines, [&](std::size_t begin, std::size_t end) {
      std::size_t found = 0;
      for (std::size_t k = begin; k < end; ++k)
        if (judgeDriverVector(*oracle[k], driverVectors[k]).outside) ++found;
      outside += found;
    });
  };
  // A driver that comes up and then fails (a probe shader that does not
  // compile) skips its row; the other rows still run.
  try {
    // The probe shader's compile and llvmpipe's first draw, before timing.
    runChunk(0, std::min<std::size_t>(1024, kBatch));
    outside = 0;
    for (auto _ : state) {
      for (std::size_t first = 0; first < kBatch; first += chunk)
        runChunk(first, std::min(chunk, kBatch - first));
    }
  } catch (const std::exception& error) {
    state.SkipWithError((backendName + ": " + error.what()).c_str());
    return;
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kBatch));
  state.counters["threads"] = pool.threads();
  // A driver's answers outside the spec are a finding, reported, not an error.
  if (backend)
    state.counters["outside_spec"] =
        static_cast<double>(outside.load()) / static_cast<double>(state.iterations());
}

// Wall time: the work is on every core, and the calling thread's CPU time
// would leave the others' out.
#define SNELL_PIPELINE(name, backend, fn)                                  \
  BENCHMARK_CAPTURE(pipeline, name, std::string(backend), std::string(fn)) \
      ->UseRealTime()                                                      \
      ->Unit(benchmark::kMillisecond)
SNELL_PIPELINE(oracle_glsl_refract, "oracle:glsl", "refract");
BENCHMARK_CAPTURE(pipeline, oracle_glsl_refract_general_road, std::string("oracle:glsl"),
                  std::string("refract"), OracleRoad::General)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
SNELL_PIPELINE(gl_refract, "gl", "refract");
SNELL_PIPELINE(oracle_vulkan_refract, "oracle:vulkan", "refract");
BENCHMARK_CAPTURE(pipeline, oracle_vulkan_refract_general_road, std::string("oracle:vulkan"),
                  std::string("refract"), OracleRoad::General)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
SNELL_PIPELINE(vk_refract, "vk", "refract");
SNELL_PIPELINE(oracle_glsl_reflect, "oracle:glsl", "reflect");
SNELL_PIPELINE(gl_reflect, "gl", "reflect");
SNELL_PIPELINE(oracle_vulkan_reflect, "oracle:vulkan", "reflect");
SNELL_PIPELINE(vk_reflect, "vk", "reflect");
// A GPU's own drivers, where the machine has one (skipped, with the reason,
// where it has none).
SNELL_PIPELINE(gl_gpu_refract, "gl:gpu", "refract");
SNELL_PIPELINE(vk_gpu_refract, "vk:gpu", "refract");
SNELL_PIPELINE(gl_gpu_reflect, "gl:gpu", "reflect");
SNELL_PIPELINE(vk_gpu_reflect, "vk:gpu", "reflect");

}  // namespace
}  // namespace snell
