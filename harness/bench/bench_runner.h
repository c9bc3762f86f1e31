#pragma once
// `snell bench`'s measurement: every method listing on every backend draws
// the scene at each resolution; its time per frame is the median of warm
// repeats (the pipeline compiled and a few frames drawn first), and its
// error is its image held against the physics reference at the largest
// resolution. Which reference a ladder needs is read from its manifests
// (bench/ladder_reference.h).
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "bench/bench_record.h"
#include "bench/dispersion_reference_image.h"
#include "core/manifest.h"

namespace snell::bench {

struct BenchOptions {
  std::filesystem::path methodsDir;  // manifests of the methods, e.g. shaders/methods/fresnel
  std::string scene = "sphere";
  std::vector<std::string> backends{"gl", "vk"};
  std::vector<int> resolutions{128, 256, 512};  // square images
  // Sphere tessellations to time at the largest resolution, as stacks (the
  // slices are twice as many, as in scenes/sphere.toml); empty: the scene's
  // own, a quarter of it and four times it. Only the sphere has them.
  std::vector<int> tessellations;
  int warmup = 3;    // untimed frames after the first draw
  int repeats = 15;  // timed frames per resolution
  // Wavelengths of a dispersion ladder's spectral reference.
  int referenceWavelengths = kReferenceWavelengths;
  // The pixels each backend drew at the largest resolution go here (EXR),
  // when not empty.
  std::filesystem::path imagesDir;
};

// The files a run writes into BenchOptions::imagesDir: each method's image
// on each backend, and the physics reference's.
std::string benchImageName(const std::string& method, const std::string& backend);
inline constexpr const char* kReferenceImageName = "physics_reference.exr";

// The ladder's methods (options.methodsDir), with what runBench refuses
// before it draws anything: its options, a manifest, a method the physics
// reference cannot be chosen for. Throws UsageError naming the file. A
// folder of ladders checks every ladder this way first, so that a later
// ladder's mistake is not found after minutes of timing earlier ones.
std::vector<Manifest> loadLadder(const BenchOptions& options);

// Runs the measurement; `progress` gets one line per method and backend.
// Throws UsageError for bad options or a listing that does not compile.
BenchResults runBench(const BenchOptions& options,
                      const std::function<void(const std::string&)>& progress);

}  // namespace snell::bench
