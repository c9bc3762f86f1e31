#include "backends/vk/spirv_output_locations.h"

#include <gtest/gtest.h>

#include <map>

#include "backends/vk/glsl_to_spirv.h"
#include "backends/vk/spirv_validate.h"
#include "core/fragment_probes.h"

namespace snell::vk {
namespace {

// SPIR-V numbers spelt out from the SPIR-V 1.6 spec, not the header the pass uses.
constexpr std::uint32_t kOpName = 5, kOpDecorate = 71, kDecorationLocation = 30;

const char* kVertex = R"(#version 140
in vec4 Position;
out vec3 V;
void main() { V = Position.xyz; gl_Position = Position; }
)";

// The probes' outputs are declared before the listing's own, so glslang's
// automatic locations put the listing's output last.
const char* kFragment = R"(#version 140
in vec3 V;
out vec4 Colour;
void main() {
  vec3 n = normalize(V);
  float d = dot(n, V);
  Colour = vec4(n, d);
}
)";

// Probes on the lines that compute n and d (`nLine` and the next).
std::vector<std::uint32_t> fragmentWithProbes(const char* fragment, int nLine = 5) {
  ProgramSource source;
  source.vertex = kVertex;
  source.fragment = insertFragmentProbes(fragment, "f.frag",
                                         {{"d", ValueType::Float, nLine + 1}, {"n", ValueType::Vec3, nLine}},
                                         ProbeOutputStyle::Outputs);
  const VulkanProgram program = compileForVulkan(source);
  EXPECT_TRUE(program.ok) << program.log;
  return program.fragmentSpirv;
}

// Location decorations by variable name.
std::map<std::string, std::uint32_t> locations(const std::vector<std::uint32_t>& words) {
  std::map<std::uint32_t, std::string> names;
  std::map<std::string, std::uint32_t> out;
  std::map<std::uint32_t, std::uint32_t> byId;
  for (std::size_t at = 5; at < words.size();) {
    const std::uint32_t count = words[at] >> 16, opcode = words[at] & 0xffff;
    if (opcode == kOpName) names[words[at + 1]] = reinterpret_cast<const char*>(&words[at + 2]);
    if (opcode == kOpDecorate && words[at + 2] == kDecorationLocation)
      byId[words[at + 1]] = words[at + 3];
    at += count;
  }
  for (const auto& [id, location] : byId) out[names[id]] = location;
  return out;
}

TEST(SpirvOutputLocations, ProbesGoToTheirLocationsAndTheListingsOutputToZero) {
  const std::vector<std::uint32_t> spirv = fragmentWithProbes(kFragment);
  const OutputLocationResult result = assignProbeOutputLocations(spirv);
  ASSERT_TRUE(result.ok()) << result.error;
  EXPECT_EQ(validateSpirvForVulkan(result.spirv), "");
  const auto placed = locations(result.spirv);
  EXPECT_EQ(placed.at("snell_probe_1"), 1u);
  EXPECT_EQ(placed.at("snell_probe_2"), 2u);
  EXPECT_EQ(placed.at("Colour"), 0u);
  EXPECT_EQ(placed.at("V"), locations(spirv).at("V"));  // inputs are left alone
}

TEST(SpirvOutputLocations, TwoListingOutputsAreAnError) {
  const char* twoOutputs = R"(#version 140
in vec3 V;
out vec4 Colour;
out vec4 Extra;
void main() {
  vec3 n = normalize(V);
  float d = dot(n, V);
  Colour = vec4(n, d); Extra = Colour;
}
)";
  const OutputLocationResult result = assignProbeOutputLocations(fragmentWithProbes(twoOutputs, 6));
  EXPECT_FALSE(result.ok());
  EXPECT_NE(result.error.find("2 outputs besides the probes"), std::string::npos) << result.error;
}

TEST(SpirvOutputLocations, MalformedModulesAreErrorsNotCrashes) {
  std::vector<std::uint32_t> spirv = fragmentWithProbes(kFragment);
  spirv.resize(spirv.size() / 2 + 1);  // cut inside an instruction
  EXPECT_FALSE(assignProbeOutputLocations(spirv).ok());
  EXPECT_FALSE(assignProbeOutputLocations(std::vector<std::uint32_t>{1, 2}).ok());
}

}  // namespace
}  // namespace snell::vk
