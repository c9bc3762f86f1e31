#pragma once
// What one backend gave at one sweep point, and what the spec allows there.
#include <string>
#include <vector>

namespace snell::sweep {

struct Observation {
  bool answered = false;  // false: the backend crashed or hung before answering
  std::string problem;    // when not answered: how the backend ended
  bool timedOut = false;  // not answered within --timeout (a hang, or a limit set too short)
  std::vector<double>
      value;  // the backend's fp32 result (the oracle's: its strict fp32 evaluation)
  std::vector<double> exact;   // exact math on the fp32 inputs
  std::vector<double> lo, hi;  // the spec's interval, hull over the ways a branch may go
  bool withinSpec = false;
  bool undefined = false;  // the spec leaves some component open (NaN input, say)
  double slack = 0;        // observed error / allowed error, worst component (inf: outside)
};

// Observations of every point on one backend, in point order.
struct BackendSweep {
  std::string backend;  // "oracle", "gl", "vk", ...
  std::string renderer;
  std::vector<Observation> points;
};

}  // namespace snell::sweep
