#pragma once
// One descriptor set layout for both stages of a linked program.
//
// glslang numbers each stage's descriptors on its own: in Listings 14.1/14.2
// the vertex stage's gl_DefaultUniformBlock and the fragment stage's
// samplerCube are both set 0, binding 0, and when the fragment stage has
// loose uniforms too, its copy of the shared block is binding 1 while the
// vertex stage's is binding 0. No single layout can describe that. So the
// modules are rewritten: every descriptor gets set 0 and one binding per
// name, the same in both stages (the linked program shares a uniform of one
// name between them), numbered in the order the stages declare them. The
// layout is then read back from the rewritten modules, not from the plan,
// so that it is what the shaders really say.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "backends/vk/spirv_resources.h"

namespace snell::vk {

struct ProgramDescriptor {
  std::string name;
  DescriptorKind kind = DescriptorKind::Other;
  bool cube = false;
  bool plain2D = false;       // sampler2D (spirv_resources.h)
  std::uint32_t binding = 0;  // in set 0
  bool inVertexStage = false;
  bool inFragmentStage = false;
};

struct BoundProgram {
  std::vector<std::uint32_t> vertexSpirv;    // rewritten
  std::vector<std::uint32_t> fragmentSpirv;  // rewritten
  std::vector<ProgramDescriptor> descriptors;
};

// Throws SetupError when a module cannot be read or rewritten, or when the
// stages declare one name as two different kinds of descriptor.
BoundProgram bindProgramDescriptors(std::span<const std::uint32_t> vertexSpirv,
                                    std::span<const std::uint32_t> fragmentSpirv);

}  // namespace snell::vk
