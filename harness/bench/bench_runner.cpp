#include "bench/bench_runner.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <map>

#include "backends/backend.h"
#include "bench/ladder_reference.h"
#include "compare/image_io.h"
#include "core/case.h"
#include "core/errors.h"
#include "core/manifest.h"
#include "core/scene.h"
#include "core/scene_file.h"
#include "runner/image_check.h"
#include "runner/interrupt_flag.h"

namespace snell::bench {
namespace {

Image renderOrThrow(Backend& backend, const RenderJob& job, const Manifest& m) {
  RenderOutcome outcome = backend.render(job);
  if (!outcome.compile.ok)
    throw UsageError(fmt::format("{}: does not compile on {}:\n{}", m.path.string(), backend.name(),
                                 outcome.compile.log));
  return std::move(outcome.image);
}

FrameTiming timeFrames(Backend& backend, const RenderJob& job, const Manifest& m,
                       const BenchOptions& options) {
  renderOrThrow(backend, job, m);  // compiles and caches the pipeline
  for (int k = 0; k < options.warmup; ++k) renderOrThrow(backend, job, m);
  std::vector<double> ms;
  for (int k = 0; k < options.repeats; ++k) {
    const auto start = std::chrono::steady_clock::now();
    renderOrThrow(backend, job, m);
    const auto end = std::chrono::steady_clock::now();
    ms.push_back(std::chrono::duration<double, std::milli>(end - start).count());
  }
  FrameTiming t;
  t.width = job.width;
  t.height = job.height;
  t.repeats = options.repeats;
  t.medianMs = median(ms);
  t.p10Ms = percentile(ms, 10.0);
  t.p90Ms = percentile(ms, 90.0);
  t.minMs = *std::min_element(ms.begin(), ms.end());
  t.maxMs = *std::max_element(ms.begin(), ms.end());
  return t;
}

// A sphere at each tessellation asked (fewest vertices first), drawn at
// `size` pixels square; none for a scene that is not a sphere and was asked
// for none.
struct TessellatedScene {
  int stacks = 0, slices = 0;
  bool own = false;  // the scene file's own: timed already, at the largest resolution
  Scene scene;
};

std::vector<TessellatedScene> tessellatedScenes(const BenchOptions& options, int size) {
  SceneFile file = loadSceneFile(builtInScenesDir() / (options.scene + ".toml"));
  if (file.shape != "sphere") {
    if (!options.tessellations.empty())
      throw UsageError(fmt::format(
          "--tessellations: scene `{}` is a {}, not a sphere; drop --tessellations or use "
          "--scene sphere",
          options.scene, file.shape));
    return {};
  }
  std::vector<int> stacks = options.tessellations;
  if (stacks.empty()) stacks = {std::max(2, file.stacks / 4), file.stacks, file.stacks * 4};
  std::sort(stacks.begin(), stacks.end());
  stacks.erase(std::unique(stacks.begin(), stacks.end()), stacks.end());
  std::vector<TessellatedScene> scenes;
  for (int n : stacks) {
    SceneFile changed = file;
    changed.stacks = n;
    // The scene's own ratio of slices to stacks (2 on scenes/sphere.toml).
    changed.slices = std::max(3, n * file.slices / file.stacks);
    changed.width = size;
    changed.height = size;
    scenes.push_back({changed.stacks, changed.slices,
                      changed.stacks == file.stacks && changed.slices == file.slices,
                      buildScene(changed)});
  }
  return scenes;
}

void checkOptions(const BenchOptions& options) {
  for (int n : options.tessellations)
    if (n < 2 || n > 1024)
      throw UsageError(fmt::format("--tessellations: {} stacks is outside 2 to 1024", n));
  if (options.resolutions.empty()) throw UsageError("--resolutions: give at least one size");
  for (int r : options.resolutions)
    if (r < 8 || r > 4096)
      throw UsageError(fmt::format("--resolutions: {} is outside 8 to 4096 pixels", r));
  if (options.repeats < 1) throw UsageError("--repeats: time at least one frame");
  if (options.warmup < 0) throw UsageError("--warmup: cannot be negative");
  if (options.backends.empty()) throw UsageError("--backends: give at least one backend");
  if (options.referenceWavelengths < 1 || options.referenceWavelengths > 4096)
    throw UsageError(fmt::format("reference wavelengths: {} is outside 1 to 4096",
                                 options.referenceWavelengths));
}

}  // namespace

std::vector<Manifest> loadLadder(const BenchOptions& options) {
  checkOptions(options);
  std::vector<Manifest> methods = loadManifests(options.methodsDir);
  if (methods.empty())
    throw UsageError(fmt::format("{}: no method manifests (manifest.toml) found here",
                                 options.methodsDir.string()));
  LadderReference::check(methods);
  return methods;
}

BenchResults runBench(const BenchOptions& options,
                      const std::function<void(const std::string&)>& progress) {
  const std::vector<Manifest> methods = loadLadder(options);
  const Scene baseScene = makeScene(options.scene);
  const int errorSize = options.resolutions.back();

  BenchResults results;
  results.scene = options.scene;
  const std::vector<TessellatedScene> tessellations = tessellatedScenes(options, errorSize);
  const LadderReference references(methods, baseScene, errorSize, options.referenceWavelengths);
  results.reference = references.model();

  // Every method is drawn once on every backend before any is timed: one
  // that does not compile stops the bench before minutes of timing, not
  // after (the pipelines stay compiled for the timing).
  std::vector<std::unique_ptr<Backend>> backends;
  for (const std::string& backendName : options.backends) {
    backends.push_back(makeBackend(backendName, {}));
    for (const Manifest& m : methods) {
      Scene scene = baseScene;
      scene.width = scene.height = options.resolutions.front();
      renderOrThrow(*backends.back(), sceneRenderJob(m, scene, resolveBindings(m, scene)), m);
    }
  }

  const std::size_t total = backends.size() * methods.size();
  for (std::unique_ptr<Backend>& backend : backends) {
    for (const Manifest& m : methods) {
      if (const int signal = interruptReceived())
        throw Interrupted(
            signal,
            fmt::format("bench interrupted by {} after {} of {} methods of {} were measured: "
                        "bench.json, the table, the charts and the images are written when a "
                        "ladder ends, so none was written for it (an earlier run's stay as they "
                        "were; ladders finished before it are kept)",
                        signalName(signal), results.records.size(), total,
                        options.methodsDir.string()));
      BenchRecord record;
      record.method = m.id;
      record.title = m.title;
      record.backend = backend->name();
      record.renderer = backend->driverInfo().renderer;
      record.parameters = std::map<std::string, double>(m.constants.begin(), m.constants.end());
      Image lastImage;
      for (int size : options.resolutions) {
        Scene scene = baseScene;
        scene.width = size;
        scene.height = size;
        const RenderJob job = sceneRenderJob(m, scene, resolveBindings(m, scene));
        record.timings.push_back(timeFrames(*backend, job, m, options));
        if (size == errorSize) lastImage = renderOrThrow(*backend, job, m);
      }
      for (const TessellatedScene& tessellated : tessellations) {
        const Scene& scene = tessellated.scene;
        TessellationTiming t;
        t.stacks = tessellated.stacks;
        t.slices = tessellated.slices;
        t.vertices = scene.vertexCount;
        t.triangles = scene.indices.size() / 3;
        t.timing = tessellated.own
                       ? record.timings.back()
                       : timeFrames(*backend, sceneRenderJob(m, scene, resolveBindings(m, scene)),
                                    m, options);
        record.byTessellation.push_back(t);
      }
      const ReferenceImage& reference = references.imageFor(m);
      record.error = imageError(lastImage, reference.color, reference.covered);
      record.errorWidth = errorSize;
      record.errorByAngle = errorByAngle(lastImage, reference);
      if (!options.imagesDir.empty())
        writeImageAtomically(options.imagesDir / benchImageName(m.id, record.backend), lastImage);
      progress(fmt::format("{} on {}: {:.3f} ms per frame at {}px, CIEDE2000 mean {:.3f}", m.id,
                           record.backend, record.msPerFrame(), errorSize, record.error.deMean));
      results.records.push_back(std::move(record));
    }
  }
  if (!options.imagesDir.empty())
    writeImageAtomically(options.imagesDir / kReferenceImageName, references.first().color);
  return results;
}

std::string benchImageName(const std::string& method, const std::string& backend) {
  std::string stem = method;
  std::replace(stem.begin(), stem.end(), '/', '_');
  return fmt::format("{}.{}.exr", stem, backend);
}

}  // namespace snell::bench
