#include "backends/vk/compiled_program_store.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "vk_test_support.h"

namespace snell::vk {
namespace {

namespace fs = std::filesystem;

ProgramSource listing14_1() {
  ProgramSource program;
  program.vertex = vktest::readSourceFile("shaders/orange-book/14.1-fresnel/fresnel.vert");
  program.fragment = vktest::readSourceFile("shaders/orange-book/14.1-fresnel/fresnel.frag");
  program.vertexPath = "shaders/orange-book/14.1-fresnel/fresnel.vert";
  program.fragmentPath = "shaders/orange-book/14.1-fresnel/fresnel.frag";
  return program;
}

// A legacy listing: the adapter's block derives GL state, and its inputs
// are reported under the built-ins' names.
ProgramSource legacyProgram() {
  ProgramSource legacy = vktest::vertexProgram(
      "varying vec3 n;\nvoid main() { n = gl_NormalMatrix * gl_Normal; gl_Position = "
      "ftransform(); }\n",
      "probes/legacy.vert");
  legacy.profile = Profile::Compatibility;
  return legacy;
}

// Compiles with a warning and without: the log and diagnostics must come back too.
ProgramSource brokenProgram() {
  return vktest::vertexProgram("#version 140\nvoid main() { gl_Position = vec4(1.0) +; }\n",
                               "probes/broken.vert");
}

void expectSame(const VulkanProgram& a, const VulkanProgram& b) {
  EXPECT_EQ(a.ok, b.ok);
  EXPECT_EQ(a.log, b.log);
  ASSERT_EQ(a.diagnostics.size(), b.diagnostics.size());
  for (std::size_t k = 0; k < a.diagnostics.size(); ++k) {
    EXPECT_EQ(a.diagnostics[k].stage, b.diagnostics[k].stage);
    EXPECT_EQ(a.diagnostics[k].line, b.diagnostics[k].line);
    EXPECT_EQ(a.diagnostics[k].error, b.diagnostics[k].error);
    EXPECT_EQ(a.diagnostics[k].message, b.diagnostics[k].message);
  }
  EXPECT_EQ(a.vertexSpirv, b.vertexSpirv);
  EXPECT_EQ(a.fragmentSpirv, b.fragmentSpirv);
  ASSERT_EQ(a.uniformBlock.has_value(), b.uniformBlock.has_value());
  if (a.uniformBlock) {
    EXPECT_EQ(a.uniformBlock->packing, b.uniformBlock->packing);
    EXPECT_EQ(a.uniformBlock->size, b.uniformBlock->size);
    EXPECT_EQ(a.uniformBlock->derivesLegacyState, b.uniformBlock->derivesLegacyState);
    ASSERT_EQ(a.uniformBlock->members.size(), b.uniformBlock->members.size());
    for (std::size_t k = 0; k < a.uniformBlock->members.size(); ++k) {
      const BlockMember& x = a.uniformBlock->members[k];
      const BlockMember& y = b.uniformBlock->members[k];
      EXPECT_EQ(x.name, y.name);
      EXPECT_EQ(x.offset, y.offset);
      EXPECT_EQ(x.type, y.type);
      EXPECT_EQ(x.declaredType, y.declaredType);
    }
  }
  ASSERT_EQ(a.vertexInputs.size(), b.vertexInputs.size());
  for (std::size_t k = 0; k < a.vertexInputs.size(); ++k) {
    EXPECT_EQ(a.vertexInputs[k].name, b.vertexInputs[k].name);
    EXPECT_EQ(a.vertexInputs[k].location, b.vertexInputs[k].location);
    EXPECT_EQ(a.vertexInputs[k].components, b.vertexInputs[k].components);
    EXPECT_EQ(a.vertexInputs[k].declaredType, b.vertexInputs[k].declaredType);
  }
}

TEST(VkCompiledProgramStore, EveryFieldReadsBack) {
  for (const ProgramSource& source : {listing14_1(), legacyProgram(), brokenProgram()}) {
    SCOPED_TRACE(source.vertexPath);
    const VulkanProgram compiled = compileForVulkan(source);
    const Digest key = compiledProgramKey(source);
    const std::optional<VulkanProgram> back =
        decodeCompiledProgram(key, encodeCompiledProgram(key, compiled));
    ASSERT_TRUE(back.has_value());
    expectSame(compiled, *back);
  }
  // The three cover the optional parts: a block that derives GL state, a
  // program with none, and a failure with its log.
  EXPECT_TRUE(compileForVulkan(legacyProgram()).uniformBlock->derivesLegacyState);
  EXPECT_FALSE(compileForVulkan(brokenProgram()).ok);
  EXPECT_FALSE(compileForVulkan(brokenProgram()).log.empty());
}

TEST(VkCompiledProgramStore, DamagedOrForeignBytesReadAsNothing) {
  const ProgramSource source = listing14_1();
  const Digest key = compiledProgramKey(source);
  const std::string bytes = encodeCompiledProgram(key, compileForVulkan(source));
  ASSERT_TRUE(decodeCompiledProgram(key, bytes).has_value());
  std::string flipped = bytes;
  flipped[bytes.size() / 2] = static_cast<char>(flipped[bytes.size() / 2] ^ 1);
  EXPECT_FALSE(decodeCompiledProgram(key, flipped).has_value());
  EXPECT_FALSE(decodeCompiledProgram(key, bytes.substr(0, bytes.size() - 1)).has_value());
  EXPECT_FALSE(decodeCompiledProgram(key, bytes + "x").has_value());
  EXPECT_FALSE(decodeCompiledProgram(compiledProgramKey(legacyProgram()), bytes).has_value());
  EXPECT_FALSE(decodeCompiledProgram(key, "").has_value());
}

TEST(VkCompiledProgramStore, EveryPartOfTheSourceChangesTheKey) {
  const ProgramSource base = listing14_1();
  const Digest key = compiledProgramKey(base);
  EXPECT_EQ(compiledProgramKey(listing14_1()), key);
  ProgramSource changed = base;
  changed.vertex += " ";
  EXPECT_NE(compiledProgramKey(changed), key);
  changed = base;
  changed.fragment += " ";
  EXPECT_NE(compiledProgramKey(changed), key);
  changed = base;
  changed.vertexPath = "elsewhere.vert";
  EXPECT_NE(compiledProgramKey(changed), key);
  changed = base;
  changed.fragmentPath = "elsewhere.frag";
  EXPECT_NE(compiledProgramKey(changed), key);
  changed = base;
  changed.profile = Profile::Compatibility;
  EXPECT_NE(compiledProgramKey(changed), key);
  // The text and its path are separate fields.
  ProgramSource moved = base;
  moved.vertex = base.vertex + base.vertexPath;
  moved.vertexPath = "";
  EXPECT_NE(compiledProgramKey(moved), key);
}

class VkCompiledProgramStoreFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("snell-compiled-programs-" + std::to_string(::getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::size_t files() const {
    std::size_t n = 0;
    if (fs::exists(dir_))
      for (const auto& entry : fs::recursive_directory_iterator(dir_)) n += entry.is_regular_file();
    return n;
  }
  fs::path dir_;
};

TEST_F(VkCompiledProgramStoreFiles, ACompileIsKeptAndReadBackInsteadOfCompiled) {
  const CompiledProgramStore store(dir_);
  const ProgramSource source = listing14_1();
  const VulkanProgram first = store.compile(source);
  ASSERT_TRUE(first.ok) << first.log;
  EXPECT_EQ(files(), 1u);
  expectSame(store.compile(source), first);
  EXPECT_EQ(files(), 1u);

  // A program planted under the key is what comes back: the store is
  // really read, not compiled again.
  VulkanProgram planted = first;
  planted.log = "planted";
  const Digest key = compiledProgramKey(source);
  ASSERT_TRUE(KeyedFileStore(dir_).write(key, encodeCompiledProgram(key, planted)));
  EXPECT_EQ(store.compile(source).log, "planted");
}

TEST_F(VkCompiledProgramStoreFiles, AFailureIsKeptWithItsLog) {
  const CompiledProgramStore store(dir_);
  const VulkanProgram first = store.compile(brokenProgram());
  EXPECT_FALSE(first.ok);
  EXPECT_EQ(files(), 1u);
  expectSame(store.compile(brokenProgram()), first);
  expectSame(first, compileForVulkan(brokenProgram()));
}

TEST_F(VkCompiledProgramStoreFiles, NoFolderKeepsNothing) {
  const CompiledProgramStore store{fs::path()};
  EXPECT_TRUE(store.compile(listing14_1()).ok);
  EXPECT_FALSE(fs::exists(dir_));
}

TEST_F(VkCompiledProgramStoreFiles, ADamagedFileIsCompiledAgainAndReplaced) {
  const CompiledProgramStore store(dir_);
  const ProgramSource source = listing14_1();
  const VulkanProgram first = store.compile(source);
  const Digest key = compiledProgramKey(source);
  ASSERT_TRUE(KeyedFileStore(dir_).write(key, "not a program"));
  expectSame(store.compile(source), first);
  const std::optional<std::string> bytes = KeyedFileStore(dir_).read(key);
  ASSERT_TRUE(bytes.has_value());
  EXPECT_TRUE(decodeCompiledProgram(key, *bytes).has_value());
}

}  // namespace
}  // namespace snell::vk
