#include "core/fragment_probes.h"

#include "core/errors.h"

namespace snell {

ProbeOutputStyle probeOutputStyleFor(const std::string& source) {
  return source.find("gl_FragColor") != std::string::npos ||
                 source.find("gl_FragData") != std::string::npos
             ? ProbeOutputStyle::FragData
             : ProbeOutputStyle::Outputs;
}

std::string insertFragmentProbes(const std::string& source, const std::string&,
                                 const std::vector<FragmentProbe>& probes, ProbeOutputStyle) {
  if (probes.empty()) return source;
  throw SetupError("fragment probes are not implemented yet");
}

}  // namespace snell
