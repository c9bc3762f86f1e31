#include "backends/vk/spirv_resources.h"

#include <glslang/SPIRV/spirv.hpp>
#include <map>

#include "backends/vk/spirv_module.h"

namespace snell::vk {

DescriptorResources listDescriptorResources(std::span<const std::uint32_t> spirv) {
  DescriptorResources result;
  const spirv::Module module = spirv::parseModule(spirv);
  if (!module.error.empty()) {
    result.error = module.error;
    return result;
  }
  std::map<std::uint32_t, std::string> names;
  std::map<std::uint32_t, std::uint32_t> pointees;
  std::map<std::uint32_t, std::uint32_t> sets;
  std::map<std::uint32_t, std::uint32_t> bindings;
  struct Variable {
    std::uint32_t id;
    std::uint32_t pointerType;
    std::uint32_t storage;
  };
  std::vector<Variable> variables;
  for (const spirv::Instruction& inst : module.instructions) {
    const auto& ops = inst.operands;
    if (inst.opcode == spv::OpName && ops.size() >= 2) {
      if (auto name = spirv::literalString(ops, 1)) names[ops[0]] = *name;
    } else if (inst.opcode == spv::OpTypePointer && ops.size() >= 3) {
      pointees[ops[0]] = ops[2];
    } else if (inst.opcode == spv::OpDecorate && ops.size() >= 3) {
      if (ops[1] == spv::DecorationDescriptorSet) sets[ops[0]] = ops[2];
      if (ops[1] == spv::DecorationBinding) bindings[ops[0]] = ops[2];
    } else if (inst.opcode == spv::OpVariable && ops.size() >= 3) {
      const std::uint32_t storage = ops[2];
      if (storage == spv::StorageClassUniform || storage == spv::StorageClassUniformConstant ||
          storage == spv::StorageClassStorageBuffer) {
        variables.push_back({ops[1], ops[0], storage});
      }
    }
  }
  for (const Variable& variable : variables) {
    DescriptorResource resource;
    resource.name = names[variable.id];
    if (resource.name.empty()) resource.name = names[pointees[variable.pointerType]];
    resource.set = sets[variable.id];
    resource.binding = bindings[variable.id];
    resource.uniformBuffer = variable.storage == spv::StorageClassUniform;
    result.resources.push_back(std::move(resource));
  }
  return result;
}

}  // namespace snell::vk
