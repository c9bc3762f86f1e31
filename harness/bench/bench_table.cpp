#include "bench/bench_table.h"

#include <fmt/format.h>

#include <set>

#include "bench/bench_chart.h"
#include "bench/pareto_front.h"

namespace snell::bench {

std::string tessellationTable(const BenchResults& results) {
  if (results.records.empty() || results.records.front().byTessellation.empty()) return "";
  const BenchRecord& first = results.records.front();
  std::string out = fmt::format(
      "\nms per frame at {}px by sphere tessellation (stacks x slices, "
      "vertices)\n",
      first.byTessellation.front().timing.width);
  std::set<std::string> backends;
  for (const BenchRecord& r : results.records) backends.insert(r.backend);
  for (const std::string& backend : backends) {
    out += fmt::format("\n{}\n  method                 ", backend);
    for (const TessellationTiming& t : first.byTessellation)
      out += fmt::format(" {:>20}", fmt::format("{}x{} ({})", t.stacks, t.slices, t.vertices));
    out += "\n";
    for (const BenchRecord& r : results.records) {
      if (r.backend != backend) continue;
      out += fmt::format("  {:22}", shortMethodName(r.method));
      for (const TessellationTiming& t : r.byTessellation)
        out += fmt::format(" {:>20.3f}", t.timing.medianMs);
      out += "\n";
    }
  }
  return out;
}

std::string benchTable(const BenchResults& results, const std::string& metric) {
  std::string out = fmt::format("scene {}; reference: {}\n", results.scene, results.reference);
  std::set<std::string> backends;
  for (const BenchRecord& r : results.records) backends.insert(r.backend);
  for (const std::string& backend : backends) {
    std::vector<const BenchRecord*> rows;
    std::vector<CostError> costs;
    for (const BenchRecord& r : results.records) {
      if (r.backend != backend) continue;
      rows.push_back(&r);
      costs.push_back({r.msPerFrame(), errorMetric(r.error, metric)});
    }
    std::set<std::size_t> front;
    for (std::size_t i : paretoFront(costs)) front.insert(i);
    out += fmt::format("\n{} ({})\n", backend, rows.empty() ? "" : rows.front()->renderer);
    out += "  front  method                 ";
    for (const FrameTiming& t : rows.front()->timings)
      out += fmt::format(" {:>14}", fmt::format("ms@{}", t.width));
    out += "   p10-p90 ms   rms      max      dE00 mean  dE00 p95\n";
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const BenchRecord& r = *rows[i];
      out += fmt::format("  {:5}  {:22}", front.count(i) ? "*" : "", shortMethodName(r.method));
      for (const FrameTiming& t : r.timings) out += fmt::format(" {:>14.3f}", t.medianMs);
      const FrameTiming& last = r.timings.back();
      out += fmt::format("   {:5.3f}-{:<5.3f}  {:<8.5f} {:<8.5f} {:<10.4f} {:<8.4f}\n", last.p10Ms,
                         last.p90Ms, r.error.rms, r.error.max, r.error.deMean, r.error.deP95);
    }
  }
  out += tessellationTable(results);
  out += fmt::format(
      "\n* on the Pareto front of ms per frame (largest resolution) against {}: no other method "
      "is both as fast and as accurate. Errors at {}px over the pixels both images cover.\n",
      metric, results.records.empty() ? 0 : results.records.front().errorWidth);
  return out;
}

}  // namespace snell::bench
