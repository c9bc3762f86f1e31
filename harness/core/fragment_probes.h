#pragma once
// Reading values out of the fragment stage. A listing computes its
// refracted and reflected directions in locals that no API can read back;
// the probe adapter adds, after the statement that computes each one, a
// write of its value to an extra float colour output, and nothing else:
// the listing's own lines, their order and their line numbers stay as
// published. Each probe's target holds (value, 1) where the statement ran
// and (0, 0, 0, 0) elsewhere, so pixels a branch skipped are told apart.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "core/values.h"

namespace snell {

struct FragmentProbe {
  std::string expression;  // a GLSL expression in scope after `line`, usually a variable
  ValueType type = ValueType::Vec3;  // float, vec2 or vec3
  int line = 0;                      // 1-based line of the fragment source
};

// How the extra outputs are declared; probe k (from 0) goes to colour
// output k + 1, the listing's own output keeps 0.
// - Outputs: `out vec4 snell_probe_<k+1>;`, placed at its location by name
//   (OpenGL's glBindFragDataLocation, a SPIR-V pass on Vulkan), since GLSL
//   before 3.30 has no layout locations on outputs.
// - FragData: for sources that write gl_FragColor, which may not be mixed
//   with user outputs: gl_FragColor becomes gl_FragData[0] and probe k
//   writes gl_FragData[k + 1].
enum class ProbeOutputStyle { Outputs, FragData };

// "snell_probe_<index + 1>": the output the probe with this index writes.
std::string probeOutputName(std::size_t index);
// The colour output location a probe output's name asks for
// ("snell_probe_3" -> 3), or nullopt for any other name.
std::optional<int> probeOutputLocation(const std::string& name);

// The style an OpenGL source needs: FragData when it writes gl_FragColor or
// gl_FragData, Outputs otherwise.
ProbeOutputStyle probeOutputStyleFor(const std::string& source);

// The source with the probes' writes added. Throws UsageError
// "PATH:LINE: ..." when a probe's line is outside main(), does not end a
// statement, or the source has no main().
std::string insertFragmentProbes(const std::string& source, const std::string& path,
                                 const std::vector<FragmentProbe>& probes, ProbeOutputStyle style);

}  // namespace snell
