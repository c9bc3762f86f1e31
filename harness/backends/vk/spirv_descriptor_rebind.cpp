#include "backends/vk/spirv_descriptor_rebind.h"

#include <glslang/SPIRV/spirv.hpp>
#include <set>

#include "backends/vk/spirv_module.h"

namespace snell::vk {

RebindResult rebindDescriptors(std::span<const std::uint32_t> spirv,
                               const std::map<std::uint32_t, DescriptorSlot>& slots) {
  RebindResult result;
  const spirv::Module module = spirv::parseModule(spirv);
  if (!module.error.empty()) {
    result.error = module.error;
    return result;
  }
  std::vector<std::uint32_t> words(spirv.begin(), spirv.end());
  std::set<std::uint32_t> setDecorated, bindingDecorated;
  for (const spirv::Instruction& inst : module.instructions) {
    const auto& ops = inst.operands;
    if (inst.opcode != spv::OpDecorate || ops.size() < 3) continue;
    const auto slot = slots.find(ops[0]);
    if (slot == slots.end()) continue;
    // The literal is the instruction's fourth word: opcode, target, decoration, value.
    std::uint32_t& value = words[inst.offset + 3];
    if (ops[1] == spv::DecorationDescriptorSet) {
      value = slot->second.set;
      setDecorated.insert(ops[0]);
    } else if (ops[1] == spv::DecorationBinding) {
      value = slot->second.binding;
      bindingDecorated.insert(ops[0]);
    }
  }
  for (const auto& [variable, slot] : slots) {
    if (!setDecorated.count(variable) || !bindingDecorated.count(variable)) {
      result.error = "variable %" + std::to_string(variable) +
                     " lacks a DescriptorSet or Binding decoration to rewrite";
      return result;
    }
  }
  result.spirv = std::move(words);
  return result;
}

}  // namespace snell::vk
