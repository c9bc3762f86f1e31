#pragma once
// One draw of a listing in `snell sweep`: the listing at one eta, in one
// frame (unit or stretched), with every sweep point as a vertex. The sweep
// and its driver children build the same draw from the same description,
// so only the description crosses the process boundary. No graphics API.
#include <optional>
#include <string>
#include <vector>

#include "core/case.h"
#include "core/manifest.h"
#include "sweep/listing_eta.h"
#include "sweep/listing_geometry.h"
#include "sweep/sweep_points.h"

namespace snell::sweep {

struct DrawSpec {
  std::string manifestPath;
  std::string frame = "unit";  // "unit" or "stretched"
  double eta = 0;              // 0: as published (also for a listing without an eta)
  bool quick = false;          // quickGrid() in place of fullGrid()
};

// Why a listing is not drawn by the sweep ("" when it is): it does not
// compile as published, or it reads back nothing from its vertex stage
// (its inputs come from the fragment stage at a scene's pixels, which no
// vertex of the sweep can set).
std::string whyNotSwept(const Manifest& manifest);

struct PreparedDraw {
  DrawSpec spec;
  Manifest manifest;  // with the swept eta in its constants and uniforms
  ProgramSource program;
  EtaBinding eta;
  double etaValue = 0;  // the main eta of this draw (0: none)
  std::vector<ListingPoint> points;
  bool diffraction = false;  // points where dot(N, H) -> 0 were added
  Scene scene;
  ResolvedBindings bindings;
};

// Throws UsageError when the manifest cannot be read or bound (a bug in
// the catalog, not a sweep point) and SetupError when the eta cannot be
// set (the message says why).
PreparedDraw prepareDraw(const DrawSpec& spec, const Scene& base);

// The draw as one line of the driver child's job file, and back.
std::string drawLine(const DrawSpec& spec);
DrawSpec parseDrawLine(const std::string& line);

}  // namespace snell::sweep
