#include "sweep/listing_sweep.h"

#include <fmt/format.h>
#include <fnmatch.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <future>
#include <map>

#include "core/errors.h"
#include "core/scene.h"
#include "oracle/vertex_oracle.h"
#include "runner/interrupt_flag.h"
#include "sweep/listing_capture.h"

namespace snell::sweep {
namespace {

// The oracle's answer for the draw's captured outputs, in capture order.
std::vector<OracleVarying> oracleFor(const PreparedDraw& draw, PrecisionRules rules) {
  const std::unique_ptr<VertexOracle> oracle = makeVertexOracle(draw.manifest.oracle);
  std::vector<OracleVarying> all =
      oracle->evaluate({draw.bindings.uniforms, draw.manifest.constants, draw.bindings.attributes,
                        draw.bindings.vertexCount, rules});
  std::vector<OracleVarying> captured;
  for (const std::string& name : draw.manifest.captureVertex)
    for (OracleVarying& v : all)
      if (v.name == name) captured.push_back(std::move(v));
  return captured;
}

// RefractR is computed with EtaR: its own critical angle.
std::map<std::string, double> outputEtas(const PreparedDraw& draw) {
  std::map<std::string, double> etas;
  for (const std::string& output : draw.manifest.captureVertex)
    for (const std::string& constant : draw.eta.constants) {
      if (output.size() < 1 || constant.size() < 4) continue;
      const std::string suffix = constant.substr(3);
      if (output.size() > suffix.size() &&
          output.compare(output.size() - suffix.size(), suffix.size(), suffix) == 0)
        etas[output] = draw.manifest.constants.at(constant);
    }
  return etas;
}

bool literalMatrix(const Manifest& m) {
  for (const Binding& u : m.uniforms)
    if (std::holds_alternative<Value>(u.source)) {
      const ValueType type = std::get<Value>(u.source).type;
      if (type == ValueType::Mat3 || type == ValueType::Mat4) return true;
    }
  return false;
}

}  // namespace

std::vector<DrawSpec> listingDraws(const Manifest& manifest, bool quick) {
  const std::string path = manifest.path.string();
  std::vector<DrawSpec> draws = {{path, "unit", 0, quick}, {path, "stretched", 0, quick}};
  const EtaBinding binding = etaBinding(manifest);
  if (binding.empty()) return draws;
  const SweepGrid grid = quick ? quickGrid() : fullGrid();
  for (double eta : grid.etas)
    if (std::abs(eta - binding.published) > 1e-9) draws.push_back({path, "unit", eta, quick});
  return draws;
}

ListingSweepResult runListingSweep(const ListingSweepOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  ListingSweepResult result;
  std::vector<DrawSpec> draws;
  const Scene base = makeScene("sweep");
  for (const Manifest& m : loadManifests(options.shadersDir)) {
    if (!options.filter.empty() && fnmatch(options.filter.c_str(), m.id.c_str(), 0) != 0) continue;
    if (const std::string why = whyNotSwept(m); !why.empty()) {
      result.notSwept.push_back({m.id, why});
      continue;
    }
    std::vector<DrawSpec> mine = listingDraws(m, options.quick);
    const EtaBinding binding = etaBinding(m);
    if (binding.empty()) {
      result.notes.push_back(
          {m.id, "no eta constant or literal eta uniform: swept over angle at its own values"});
    } else if (mine.size() > 2) {
      // An eta the sweep cannot write into the program: as published only.
      try {
        prepareDraw(mine[2], base);
      } catch (const SetupError& error) {
        result.notes.push_back({m.id, fmt::format("eta not swept: {}", error.what())});
        mine.resize(2);
      }
    }
    if (literalMatrix(m))
      result.notes.push_back({m.id,
                              "a literal matrix in the manifest turns some outputs: the "
                              "direction checks (wrong side, against physics) are skipped"});
    result.swept.push_back(m.id);
    draws.insert(draws.end(), mine.begin(), mine.end());
  }
  result.draws = draws.size();
  std::filesystem::create_directories(options.outDir);
  const std::filesystem::path jobFile = options.outDir / kListingJobFile;
  {
    std::ofstream job(jobFile);
    for (const DrawSpec& d : draws) job << drawLine(d) << '\n';
    if (!job)
      throw SetupError(jobFile.string() + ": cannot write the sweep's job file; check --out");
  }
  // The drivers run side by side, each in its own children.
  std::vector<std::future<std::vector<DrawCapture>>> running;
  for (const std::string& backend : options.backends)
    running.push_back(std::async(std::launch::async, [&, backend] {
      return captureDraws(options.executable, backend, options.driverArgs, jobFile, draws.size(),
                          options.timeoutSeconds);
    }));
  std::vector<std::vector<DrawCapture>> captures;
  for (auto& r : running) captures.push_back(r.get());
  if (interruptReceived()) {
    std::filesystem::remove(jobFile);
    return result;  // the caller stops the sweep
  }

  for (std::size_t d = 0; d < draws.size(); ++d) {
    const PreparedDraw draw = prepareDraw(draws[d], base);
    result.vertices += draw.points.size();
    ListingDrawView view{draw.manifest.id, draws[d].frame,   draw.etaValue,
                         &draw.points,     outputEtas(draw), !literalMatrix(draw.manifest)};
    std::map<PrecisionRules, std::vector<OracleVarying>> expected;
    std::vector<ListingBackendView> backends;
    for (std::size_t b = 0; b < options.backends.size(); ++b) {
      const DrawCapture& c = captures[b][d];
      const PrecisionRules rules = options.rules.at(b);
      if (!expected.count(rules)) expected[rules] = oracleFor(draw, rules);
      backends.push_back({options.backends[b], c.answered, c.problem, c.compiled, c.log,
                          &expected.at(rules), &c.varyings, c.timedOut});
    }
    auto append = [&](std::vector<ListingBreak> more) {
      result.breaks.insert(result.breaks.end(), std::make_move_iterator(more.begin()),
                           std::make_move_iterator(more.end()));
    };
    for (const ListingBackendView& b : backends) {
      append(classifyListingDraw(view, b));
      for (ListingCriticalAngle& c : listingCriticalAngles(view, b))
        result.criticalAngles.push_back(std::move(c));
    }
    for (std::size_t a = 0; a < backends.size(); ++a)
      for (std::size_t b = a + 1; b < backends.size(); ++b)
        append(listingDisagreements(view, backends[a], backends[b]));
  }
  std::filesystem::remove(jobFile);
  result.wallSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace snell::sweep
