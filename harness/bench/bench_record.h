#pragma once
// What `snell bench` measures, and its JSON form (what `snell advise`
// reads back). One record per method and backend.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "bench/angle_error.h"
#include "bench/image_error.h"

namespace snell::bench {

// Time per frame at one resolution: a render call (draw and read-back of
// the RGBA32F image) after the pipeline was compiled and warmed up.
struct FrameTiming {
  int width = 0;
  int height = 0;
  int repeats = 0;
  double medianMs = 0;
  double minMs = 0;
  double maxMs = 0;
  double p10Ms = 0;  // the spread: 10th and 90th percentiles
  double p90Ms = 0;
};

// Time per frame with the sphere tessellated into `stacks` x `slices`, at
// the largest resolution: how the cost grows with the vertex count.
struct TessellationTiming {
  int stacks = 0;
  int slices = 0;
  std::size_t vertices = 0;
  std::size_t triangles = 0;
  FrameTiming timing;
};

struct BenchRecord {
  std::string method;  // the manifest id
  std::string title;
  std::string backend;  // "gl", "vk"
  std::string renderer;
  std::map<std::string, double> parameters;  // the manifest's constants (Eta, Wavelengths, ...)
  std::vector<FrameTiming> timings;          // one per resolution, in the order asked
  ImageError error;                          // at the largest resolution
  int errorWidth = 0;
  std::vector<AngleBin> errorByAngle;  // the same error, by angle of incidence
  // One per tessellation asked, fewest vertices first; the error is
  // measured at the scene's own tessellation only.
  std::vector<TessellationTiming> byTessellation;
  // The largest resolution's median: the cost the chart and advisor use.
  double msPerFrame() const { return timings.empty() ? 0.0 : timings.back().medianMs; }
};

struct BenchResults {
  std::string scene;
  std::string reference;  // what the physics reference models, in words
  std::vector<BenchRecord> records;
};

// Error metric names: "rms", "max" (linear RGB), "de_mean", "de_p95"
// (CIEDE2000). Unknown names throw UsageError listing the known ones.
double errorMetric(const ImageError& error, const std::string& metric);
const std::vector<std::string>& errorMetricNames();

void writeBenchResults(const BenchResults& results, const std::filesystem::path& path);
// Throws UsageError naming the file (and what is wrong) for a missing or
// malformed file.
BenchResults readBenchResults(const std::filesystem::path& path);

}  // namespace snell::bench
