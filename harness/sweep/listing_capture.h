#pragma once
// The listings' draws on a driver, in `snell sweep --listing-worker` child
// processes: the same capture path as `snell run` (Backend::
// captureVertexOutputs with the listing's program and bindings), one draw
// per listing, eta and frame. A driver that crashes or hangs takes its
// child with it: that draw is recorded as a crash and a new child goes on
// with the next.
#include <filesystem>
#include <string>
#include <vector>

#include "backends/backend.h"
#include "sweep/listing_draw.h"

namespace snell::sweep {

struct DrawCapture {
  bool answered = false;  // false: the child crashed or hung on this draw
  bool timedOut = false;  // not answered within --timeout (a hang, or a limit set too short)
  std::string problem;    // how it ended, or the set-up error
  bool compiled = false;
  std::string log;                        // the compiler's, when it did not compile
  std::vector<CapturedVarying> varyings;  // the manifest's captureVertex, in order
};

// The child's side: draws `start` onwards of `jobFile` (one drawLine each)
// on `backend`, one JSON line each on stdout. Returns the exit code.
int runListingWorker(const std::filesystem::path& jobFile, std::size_t start,
                     const std::string& backend, const BackendOptions& options);

// The sweep's side: every draw of `jobFile` on `backend`, through as many
// children as crashes need (at most `maxChildren`); a draw that gives no
// answer within `timeoutSeconds` is killed and recorded as a hang.
std::vector<DrawCapture> captureDraws(const std::string& executable, const std::string& backend,
                                      const std::vector<std::string>& driverArgs,
                                      const std::filesystem::path& jobFile, std::size_t drawCount,
                                      double timeoutSeconds, int maxChildren = 20);

// One answer line of the child (exposed for tests).
DrawCapture drawCaptureFromLine(const std::string& line);
std::string drawCaptureLine(std::size_t draw, const DrawCapture& capture);

}  // namespace snell::sweep
