#include "backends/vk/spirv_xfb_pass.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "backends/vk/glsl_to_spirv.h"
#include "backends/vk/spirv_validate.h"
#include "vk_test_support.h"

namespace snell::vk {
namespace {

using vktest::Words;

// SPIR-V numbers the tests spell out by hand, from the SPIR-V 1.6 spec,
// rather than taking them from the header the pass uses.
constexpr std::uint32_t kOpCapability = 17, kOpExecutionMode = 16, kOpDecorate = 71;
constexpr std::uint32_t kCapabilityTransformFeedback = 53, kExecutionModeXfb = 11;
constexpr std::uint32_t kDecorationOffset = 35, kDecorationXfbBuffer = 36,
                        kDecorationXfbStride = 37;

const char* kProbe = R"(#version 140
in vec4 Position;
in vec3 Normal;
uniform float Scale;
out vec3 Bent;
out float Weight;
out vec2 Spare;
void main()
{
    Bent = Normal * Scale;
    Weight = Position.w;
    Spare = Position.xy;
    gl_Position = Position;
}
)";

Words compiledProbe() {
  const VulkanProgram program = compileForVulkan(vktest::vertexProgram(kProbe, "probe.vert"));
  EXPECT_TRUE(program.ok) << program.log;
  return program.vertexSpirv;
}

XfbPassResult runPass(const Words& spirv, std::vector<std::string> names) {
  return addTransformFeedback(spirv, names);
}

// Instructions of `after` that are not in `before`, assuming `before` is a
// subsequence of `after` (which the caller checks through `preserved`).
std::vector<Words> insertedInstructions(const Words& before, const Words& after, bool& preserved) {
  const std::vector<Words> old = vktest::instructionsOf(before);
  const std::vector<Words> now = vktest::instructionsOf(after);
  std::vector<Words> inserted;
  std::size_t next = 0;
  for (const Words& inst : now) {
    if (next < old.size() && inst == old[next]) {
      ++next;
    } else {
      inserted.push_back(inst);
    }
  }
  preserved = next == old.size();
  return inserted;
}

TEST(VkSpirvXfbPass, AddsExactlyTheExpectedInstructions) {
  const Words input = compiledProbe();
  const XfbPassResult result = runPass(input, {"Weight", "Bent"});
  ASSERT_TRUE(result.ok()) << result.error;

  const std::uint32_t weight = vktest::idNamed(input, "Weight").value();
  const std::uint32_t bent = vktest::idNamed(input, "Bent").value();
  const std::uint32_t main = vktest::idNamed(input, "main").value();
  const std::uint32_t stride = 16;  // float + vec3
  std::vector<Words> expected = {
      {(2u << 16) | kOpCapability, kCapabilityTransformFeedback},
      {(3u << 16) | kOpExecutionMode, main, kExecutionModeXfb},
      {(4u << 16) | kOpDecorate, weight, kDecorationXfbBuffer, 0},
      {(4u << 16) | kOpDecorate, weight, kDecorationXfbStride, stride},
      {(4u << 16) | kOpDecorate, weight, kDecorationOffset, 0},
      {(4u << 16) | kOpDecorate, bent, kDecorationXfbBuffer, 0},
      {(4u << 16) | kOpDecorate, bent, kDecorationXfbStride, stride},
      {(4u << 16) | kOpDecorate, bent, kDecorationOffset, 4},
  };

  bool preserved = false;
  std::vector<Words> inserted = insertedInstructions(input, result.spirv, preserved);
  EXPECT_TRUE(preserved) << "the pass dropped or changed an original instruction";
  std::sort(inserted.begin(), inserted.end());
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(inserted, expected);
  EXPECT_TRUE(std::equal(input.begin(), input.begin() + 5, result.spirv.begin()))
      << "header changed";
  EXPECT_EQ(validateSpirvForVulkan(result.spirv), "");
}

TEST(VkSpirvXfbPass, ReportsTheLayoutInTheOrderAskedFor) {
  const XfbPassResult result = runPass(compiledProbe(), {"Spare", "Bent", "Weight"});
  ASSERT_TRUE(result.ok()) << result.error;
  ASSERT_EQ(result.varyings.size(), 3u);
  EXPECT_EQ(result.varyings[0].name, "Spare");
  EXPECT_EQ(result.varyings[0].components, 2);
  EXPECT_EQ(result.varyings[0].offset, 0u);
  EXPECT_EQ(result.varyings[1].name, "Bent");
  EXPECT_EQ(result.varyings[1].components, 3);
  EXPECT_EQ(result.varyings[1].offset, 8u);
  EXPECT_EQ(result.varyings[2].name, "Weight");
  EXPECT_EQ(result.varyings[2].components, 1);
  EXPECT_EQ(result.varyings[2].offset, 20u);
  EXPECT_EQ(result.stride, 24u);
}

TEST(VkSpirvXfbPass, WithoutThePassTheModuleHasNoTransformFeedback) {
  // Guards the test above: the expected instructions really are new.
  const Words input = compiledProbe();
  for (const Words& inst : vktest::instructionsOf(input)) {
    EXPECT_FALSE(inst[0] == ((2u << 16) | kOpCapability) &&
                 inst[1] == kCapabilityTransformFeedback);
    EXPECT_NE(inst[0] & 0xffff, kOpExecutionMode);
  }
}

TEST(VkSpirvXfbPass, RejectsNamesThatAreNotOutputs) {
  const Words input = compiledProbe();
  struct Case {
    std::string name;
    std::string says;
  };
  for (const Case& c :
       {Case{"Position", "'Position' is an input"},
        Case{"Scale", "'Scale' is not a vertex output"},  // a block member, not a variable
        Case{"Nowhere", "'Nowhere' is not a vertex output"}}) {
    const XfbPassResult result = runPass(input, {"Bent", c.name});
    EXPECT_FALSE(result.ok()) << c.name;
    EXPECT_NE(result.error.find(c.says), std::string::npos) << result.error;
    EXPECT_TRUE(result.spirv.empty());
  }
}

TEST(VkSpirvXfbPass, RejectsDuplicatesEmptyListsAndASecondPass) {
  const Words input = compiledProbe();
  EXPECT_NE(runPass(input, {"Bent", "Bent"}).error.find("twice"), std::string::npos);
  EXPECT_NE(runPass(input, {}).error.find("no outputs"), std::string::npos);
  const XfbPassResult once = runPass(input, {"Bent"});
  ASSERT_TRUE(once.ok()) << once.error;
  EXPECT_NE(runPass(once.spirv, {"Weight"}).error.find("already"), std::string::npos);
}

TEST(VkSpirvXfbPass, RejectsGarbage) {
  EXPECT_FALSE(runPass({}, {"Bent"}).ok());
  EXPECT_FALSE(runPass({1, 2, 3}, {"Bent"}).ok());
  EXPECT_NE(runPass({0xdeadbeef, 0x10300, 0, 100, 0}, {"Bent"}).error.find("magic"),
            std::string::npos);
  Words zeroCount = {0x07230203, 0x10300, 0, 100, 0, 0x00000011};
  EXPECT_NE(runPass(zeroCount, {"Bent"}).error.find("word count of 0"), std::string::npos);
  Words overrun = {0x07230203, 0x10300, 0, 100, 0, (9u << 16) | kOpCapability, 1};
  EXPECT_NE(runPass(overrun, {"Bent"}).error.find("runs past the end"), std::string::npos);
  // An OpName whose string never ends.
  Words unterminated = {0x07230203, 0x10300, 0, 100, 0, (3u << 16) | 5u, 7, 0x41414141};
  EXPECT_NE(runPass(unterminated, {"Bent"}).error.find("not terminated"), std::string::npos);
}

TEST(VkSpirvXfbPass, EveryTruncationFailsWithoutCrashing) {
  const Words input = compiledProbe();
  ASSERT_GT(input.size(), 50u);
  for (std::size_t length = 0; length < input.size(); ++length) {
    const Words prefix(input.begin(), input.begin() + static_cast<std::ptrdiff_t>(length));
    const XfbPassResult result = runPass(prefix, {"Bent", "Weight"});
    // A prefix that ends on an instruction boundary may get through the
    // pass, but it is still not a whole module and must not validate.
    if (result.ok()) {
      EXPECT_NE(validateSpirvForVulkan(result.spirv), "") << "length " << length;
    }
  }
}

TEST(VkSpirvXfbPass, CorruptedWordsNeverCrashThePass) {
  const Words input = compiledProbe();
  const XfbPassResult clean = runPass(input, {"Bent", "Weight"});
  ASSERT_TRUE(clean.ok()) << clean.error;
  const std::size_t addedWords = clean.spirv.size() - input.size();
  std::mt19937 random(1234);
  std::uniform_int_distribution<std::size_t> where(0, input.size() - 1);
  std::uniform_int_distribution<std::uint32_t> what;
  for (int trial = 0; trial < 2000; ++trial) {
    Words corrupted = input;
    for (int flips = 0; flips < 3; ++flips) corrupted[where(random)] = what(random);
    const XfbPassResult result = runPass(corrupted, {"Bent", "Weight"});
    // The pass only ever inserts the same fixed set of instructions.
    if (result.ok()) {
      EXPECT_EQ(result.spirv.size(), corrupted.size() + addedWords);
    }
  }
}

}  // namespace
}  // namespace snell::vk
