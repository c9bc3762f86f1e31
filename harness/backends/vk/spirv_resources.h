#pragma once
// The descriptor-backed variables a SPIR-V module declares, read from the
// module itself: glslang's reflection describes the linked program, but a
// stage's own module is what the pipeline layout has to match.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace snell::vk {

enum class DescriptorKind {
  UniformBuffer,         // a Uniform-storage Block, such as gl_DefaultUniformBlock
  CombinedImageSampler,  // a sampler* uniform that is not an array
  Other,                 // storage buffers, separate images and samplers, arrays
};

struct DescriptorResource {
  std::string name;  // the variable's name, or its block type's name when the variable has none
  std::uint32_t variableId = 0;
  std::uint32_t set = 0;
  std::uint32_t binding = 0;
  DescriptorKind kind = DescriptorKind::Other;
  bool cube = false;  // a CombinedImageSampler over a (non-arrayed) cube image: samplerCube
  // A CombinedImageSampler over a float, non-arrayed, single-sampled,
  // non-depth 2D image: sampler2D.
  bool plain2D = false;
};

struct DescriptorResources {
  std::vector<DescriptorResource> resources;  // in declaration order
  std::string error;                          // empty when the module parsed
};

DescriptorResources listDescriptorResources(std::span<const std::uint32_t> spirv);

}  // namespace snell::vk
