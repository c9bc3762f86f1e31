#pragma once
// Compiled programs kept between runs. glslang builds its tables of
// built-in declarations the first time a process compiles, and a listing's
// compile takes a few milliseconds more: together most of a Vulkan
// process's compile time, while the same build compiles the same listings
// run after run (Mesa keeps its own compiles for the same reason). A
// program that compiled is stored under a digest of the snell build (which
// holds glslang and every pass after it) and of the program's text, paths
// and profile, and read back instead of compiled when the same build meets
// the same program again. A program that does not compile is kept too
// (the as-published listings): its log is the one that build's glslang
// wrote, byte for byte.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "backends/vk/glsl_to_spirv.h"
#include "core/content_hash.h"
#include "core/keyed_file_store.h"
#include "core/program_source.h"

namespace snell::vk {

class CompiledProgramStore {
 public:
  // An empty folder keeps nothing: every program is compiled.
  explicit CompiledProgramStore(std::filesystem::path dir);

  // compileForVulkan(source), read back when this build stored it before.
  VulkanProgram compile(const ProgramSource& source) const;

 private:
  std::optional<KeyedFileStore> files_;
};

Digest compiledProgramKey(const ProgramSource& source);
std::string encodeCompiledProgram(const Digest& key, const VulkanProgram& program);
// Nothing when the bytes are not a whole compiled program stored under `key`.
std::optional<VulkanProgram> decodeCompiledProgram(const Digest& key, std::string_view bytes);

}  // namespace snell::vk
