#pragma once
// Rewrites the DescriptorSet and Binding decorations of chosen variables in
// a SPIR-V module, leaving every other word as it was.
#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <vector>

namespace snell::vk {

struct DescriptorSlot {
  std::uint32_t set = 0;
  std::uint32_t binding = 0;
};

struct RebindResult {
  std::vector<std::uint32_t> spirv;  // the rewritten module; empty on error
  std::string error;                 // empty on success
  bool ok() const { return error.empty(); }
};

// `slots` is keyed by variable id. Every such variable must already carry
// both decorations (glslang's auto-mapped bindings give them to every
// descriptor variable); one that lacks either is an error. Never throws for
// malformed SPIR-V.
RebindResult rebindDescriptors(std::span<const std::uint32_t> spirv,
                               const std::map<std::uint32_t, DescriptorSlot>& slots);

}  // namespace snell::vk
