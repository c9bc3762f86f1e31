#pragma once
// Puts a fragment module's outputs where a render with probes reads them:
// the probe outputs snell_probe_<k> (core/fragment_probes.h) at location k,
// the listing's own output at 0. GLSL before 3.30 has no layout locations
// on outputs and glslang's automatic locations follow declaration order,
// so the locations are set here, by name, in the SPIR-V.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace snell::vk {

struct OutputLocationResult {
  std::vector<std::uint32_t> spirv;  // the rewritten module; empty on error
  std::string error;                 // empty on success
  bool ok() const { return error.empty(); }
};

// Every output variable that is not a built-in must carry a Location
// decoration (glslang's automatic locations give one to each) and a name;
// exactly one of them may be other than a probe. Never throws for
// malformed SPIR-V.
OutputLocationResult assignProbeOutputLocations(std::span<const std::uint32_t> spirv);

}  // namespace snell::vk
