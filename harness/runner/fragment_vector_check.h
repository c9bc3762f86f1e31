#pragma once
// The vector half of a fragment-stage listing: render the scene with the
// manifest's probes (core/fragment_probes.h), feed the oracle, pixel by
// pixel, the values read back at the probes it names as inputs, and hold
// the values at the probes it names as outputs against its intervals.
// Starting from the driver's own values at the inputs keeps interpolation
// out of the check: the listing's lines are what is under test.
#include <cstddef>
#include <string>
#include <vector>

#include "backends/backend.h"
#include "compare/vector_check.h"
#include "core/case.h"
#include "runner/oracle_cache.h"

namespace snell {

struct FragmentVectorCheck {
  bool compiled = true;
  std::string compileLog;
  std::size_t pixels = 0;              // where every input probe was written
  std::vector<VaryingCheck> varyings;  // one per captured oracle output
  std::string failures;                // first failing components, by pixel
  std::string unwritten;               // output probes missing where the inputs were written
  double oracleSeconds = 0;
};

// Throws UsageError "FILE:LINE: ..." when the fragment captures do not fit
// the listing: a capture that is neither an input nor an output of the
// oracle, an oracle input not captured, no output captured, a probe line
// outside main() or not ending a statement, a scene that draws nothing.
// Run before any driver loads.
void checkFragmentCaptures(const Manifest& m, const ProgramSource& program, const Scene& scene);

// Throws UsageError "MANIFEST:LINE: ..." when a capture is neither an input
// nor an output of the oracle, an oracle input is not captured, or the
// scene draws nothing.
// The oracle's results come from `oracleCache` (stored across runs there).
FragmentVectorCheck checkFragmentVectors(Backend& backend, const Manifest& m, const Scene& scene,
                                         const ResolvedBindings& bindings,
                                         OracleCache& oracleCache);

}  // namespace snell
