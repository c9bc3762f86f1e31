#pragma once
// Compiles a listing as published (`#version 140`, loose uniforms, no
// locations) to Vulkan SPIR-V with glslang's relaxed Vulkan rules, and
// reports what the harness needs to feed it: the gl_DefaultUniformBlock
// layout and the vertex input locations, both from glslang's reflection.
// A compatibility-profile (legacy) listing is first passed through the
// legacy adapter (core/legacy_adapter.h); the uniforms and inputs it adds
// are reported under the built-ins' names (gl_ModelViewMatrix, gl_Vertex).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "backends/backend.h"
#include "backends/vk/uniform_block_layout.h"

namespace snell::vk {

// Where glslang's relaxed Vulkan rules put a listing's loose uniforms.
inline constexpr const char* kDefaultUniformBlock = "gl_DefaultUniformBlock";

struct VertexInput {
  std::string name;
  std::uint32_t location = 0;
  int components = 0;  // 0: not a float scalar or vector, which snell cannot feed
  std::string declaredType;
};

struct VulkanProgram {
  bool ok = false;
  std::string log;  // every line names the file it is about
  std::vector<CompileDiagnostic> diagnostics;
  std::vector<std::uint32_t> vertexSpirv;
  std::vector<std::uint32_t> fragmentSpirv;        // empty when the program has no fragment stage
  std::optional<UniformBlockLayout> uniformBlock;  // nullopt when no loose uniform is live
  std::vector<VertexInput> vertexInputs;           // live inputs only
};

// Never throws for errors in the program; they come back as ok=false and a log.
VulkanProgram compileForVulkan(const ProgramSource& program);

}  // namespace snell::vk
