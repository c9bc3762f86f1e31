#include "backends/vk/glsl_to_spirv.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <sstream>

#include "vk_test_support.h"

namespace snell::vk {
namespace {

constexpr std::uint32_t kDecorationOffset = 35, kDecorationMatrixStride = 7,
                        kDecorationLocation = 30;
constexpr std::uint32_t kOpDecorate = 71;

const char* kListingVertex = "shaders/orange-book/14.1-fresnel/fresnel.vert";
const char* kListingFragment = "shaders/orange-book/14.1-fresnel/fresnel.frag";

ProgramSource listing14_1() {
  ProgramSource program;
  program.vertex = vktest::readSourceFile(kListingVertex);
  program.fragment = vktest::readSourceFile(kListingFragment);
  program.vertexPath = kListingVertex;
  program.fragmentPath = kListingFragment;
  return program;
}

const BlockMember* member(const UniformBlockLayout& layout, const std::string& name) {
  for (const BlockMember& m : layout.members) {
    if (m.name == name) return &m;
  }
  return nullptr;
}

std::size_t footprint(ValueType type) {
  switch (type) {
    case ValueType::Mat3:
      return 2 * matrixColumnStride(BlockPacking::Std140, 3) + 12;
    case ValueType::Mat4:
      return 3 * matrixColumnStride(BlockPacking::Std140, 4) + 16;
    default:
      return sizeof(float) * static_cast<std::size_t>(componentCount(type));
  }
}

TEST(VkGlslToSpirv, Listing14_1CompilesAndLinksUnderRelaxedRules) {
  const VulkanProgram program = compileForVulkan(listing14_1());
  ASSERT_TRUE(program.ok) << program.log;
  EXPECT_EQ(program.log, "");
  EXPECT_FALSE(program.vertexSpirv.empty());
  EXPECT_FALSE(program.fragmentSpirv.empty());
  EXPECT_EQ(program.vertexSpirv.front(), 0x07230203u);
}

TEST(VkGlslToSpirv, Listing14_1UniformOffsetsComeFromReflection) {
  const VulkanProgram program = compileForVulkan(listing14_1());
  ASSERT_TRUE(program.ok) << program.log;
  ASSERT_TRUE(program.uniformBlock.has_value());
  const UniformBlockLayout& layout = *program.uniformBlock;
  EXPECT_EQ(layout.packing, BlockPacking::Std140);

  const std::map<std::string, ValueType> declared = {{"MVMatrix", ValueType::Mat4},
                                                     {"MVPMatrix", ValueType::Mat4},
                                                     {"NormalMatrix", ValueType::Mat3},
                                                     {"TextureMatrix", ValueType::Mat4}};
  std::vector<std::pair<std::size_t, ValueType>> placed;
  for (const auto& [name, type] : declared) {
    const BlockMember* m = member(layout, name);
    ASSERT_NE(m, nullptr) << name << " is missing from the reflected block";
    EXPECT_EQ(m->type, type) << name;
    EXPECT_EQ(m->offset % 16, 0u) << name << ": std140 aligns matrices to 16 bytes";
    placed.emplace_back(m->offset, type);
  }
  std::sort(placed.begin(), placed.end());
  for (std::size_t i = 0; i + 1 < placed.size(); ++i) {
    EXPECT_LT(placed[i].first, placed[i + 1].first) << "two uniforms share an offset";
    // A mat3 with 16-byte columns takes 44 bytes, so the next member is 48 on.
    EXPECT_GE(placed[i + 1].first - placed[i].first, footprint(placed[i].second))
        << "members overlap";
  }
  EXPECT_GE(layout.size, placed.back().first + footprint(placed.back().second));

  // The offsets reflection reports are the ones the generated code reads.
  std::map<std::string, std::uint32_t> spirvOffsets, spirvStrides;
  for (const auto& [name, decoration] :
       vktest::memberDecorations(program.vertexSpirv, "gl_DefaultUniformBlock")) {
    if (decoration.size() >= 3 && decoration[1] == kDecorationOffset)
      spirvOffsets[name] = decoration[2];
    if (decoration.size() >= 3 && decoration[1] == kDecorationMatrixStride)
      spirvStrides[name] = decoration[2];
  }
  for (const auto& [name, type] : declared) {
    EXPECT_EQ(spirvOffsets[name], member(layout, name)->offset) << name;
  }
  EXPECT_EQ(spirvStrides["NormalMatrix"], matrixColumnStride(layout.packing, 3));
}

TEST(VkGlslToSpirv, Listing14_1VertexInputsGetTheMappedLocations) {
  const VulkanProgram program = compileForVulkan(listing14_1());
  ASSERT_TRUE(program.ok) << program.log;
  std::map<std::string, VertexInput> inputs;
  for (const VertexInput& input : program.vertexInputs) inputs[input.name] = input;
  ASSERT_EQ(inputs.size(), 2u);
  EXPECT_EQ(inputs["MCvertex"].components, 4);
  EXPECT_EQ(inputs["MCnormal"].components, 3);
  EXPECT_NE(inputs["MCvertex"].location, inputs["MCnormal"].location);
  // The locations reflection reports are the ones decorated in the module.
  for (const char* name : {"MCvertex", "MCnormal"}) {
    const std::uint32_t id = vktest::idNamed(program.vertexSpirv, name).value();
    std::optional<std::uint32_t> location;
    for (const vktest::Words& inst : vktest::instructionsOf(program.vertexSpirv)) {
      if ((inst[0] & 0xffff) == kOpDecorate && inst[1] == id && inst[2] == kDecorationLocation)
        location = inst[3];
    }
    EXPECT_EQ(location, inputs[name].location) << name;
  }
}

TEST(VkGlslToSpirv, CompileErrorsNameTheFileOnEveryLine) {
  const VulkanProgram program =
      compileForVulkan(vktest::vertexProgram("#version 140\nin vec4 a;\nout vec3 R;\nvoid main() { "
                                             "R = undefinedThing(a); gl_Position = a; }\n",
                                             "probes/broken.vert"));
  EXPECT_FALSE(program.ok);
  EXPECT_NE(program.log.find("undefinedThing"), std::string::npos) << program.log;
  std::istringstream lines(program.log);
  int count = 0;
  for (std::string line; std::getline(lines, line); ++count) {
    EXPECT_NE(line.find("probes/broken.vert"), std::string::npos) << line;
  }
  EXPECT_GT(count, 0);
  EXPECT_TRUE(program.vertexSpirv.empty());
}

TEST(VkGlslToSpirv, LinkErrorsNameTheFiles) {
  ProgramSource program =
      vktest::vertexProgram("#version 140\nin vec4 a;\nvoid notMain() {}\n", "probes/nomain.vert");
  const VulkanProgram compiled = compileForVulkan(program);
  EXPECT_FALSE(compiled.ok);
  EXPECT_NE(compiled.log.find("probes/nomain.vert"), std::string::npos) << compiled.log;
  EXPECT_NE(compiled.log.find("entry point"), std::string::npos) << compiled.log;
}

TEST(VkGlslToSpirv, CompatibilityProfileGoesThroughTheLegacyAdapter) {
  // A GLSL 1.40 listing is unchanged by the adapter; a legacy one gets its
  // built-ins as variables, reported under the built-ins' names.
  ProgramSource modern = listing14_1();
  modern.profile = Profile::Compatibility;
  const VulkanProgram compiled = compileForVulkan(modern);
  EXPECT_TRUE(compiled.ok) << compiled.log;

  ProgramSource legacy = vktest::vertexProgram(
      "varying vec3 n;\nvoid main() { n = gl_NormalMatrix * gl_Normal; gl_Position = "
      "ftransform(); }\n",
      "probes/legacy.vert");  // no #version: GLSL 1.10
  legacy.profile = Profile::Compatibility;
  const VulkanProgram adapted = compileForVulkan(legacy);
  ASSERT_TRUE(adapted.ok) << adapted.log;
  ASSERT_TRUE(adapted.uniformBlock);
  std::vector<std::string> members;
  for (const BlockMember& member : adapted.uniformBlock->members) members.push_back(member.name);
  std::sort(members.begin(), members.end());
  EXPECT_EQ(members, (std::vector<std::string>{"gl_ModelViewProjectionMatrix", "gl_NormalMatrix"}));
}

}  // namespace
}  // namespace snell::vk
