#pragma once
// Helpers shared by the Vulkan tests. The SPIR-V helpers here are written
// independently of harness/backends/vk/spirv_module.h on purpose: a test that
// read modules with the code under test could not catch that code's mistakes.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "backends/backend.h"

namespace snell::vktest {

// A file under the source tree (e.g. "shaders/orange-book/14.1-fresnel/fresnel.vert").
std::string readSourceFile(const std::string& relativePath);

using Words = std::vector<std::uint32_t>;

// The module's instructions (opcode word included), header dropped.
std::vector<Words> instructionsOf(const Words& module);

// The id an OpName gives `name`, if any.
std::optional<std::uint32_t> idNamed(const Words& module, const std::string& name);

// Operands of every OpMemberDecorate on the struct named `structName`:
// {member index, decoration, literal...}, keyed by the member's OpMemberName.
std::vector<std::pair<std::string, Words>> memberDecorations(const Words& module,
                                                             const std::string& structName);

struct Slot {
  std::uint32_t set = 0;
  std::uint32_t binding = 0;
};

// DescriptorSet and Binding of the variable named `name`, or of the one
// whose pointee type is named `name` (how an unnamed block such as
// gl_DefaultUniformBlock is found); nullopt when there is none.
std::optional<Slot> descriptorSlot(const Words& module, const std::string& name);

// Vertex shader source with the given body, `#version 140`, for probes.
ProgramSource vertexProgram(const std::string& source, const std::string& path);

}  // namespace snell::vktest
