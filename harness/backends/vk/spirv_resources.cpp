#include "backends/vk/spirv_resources.h"

#include <glslang/SPIRV/spirv.hpp>
#include <map>
#include <set>

#include "backends/vk/spirv_module.h"

namespace snell::vk {

namespace {

struct ImageType {
  std::uint32_t sampledType = 0;
  std::uint32_t dim = 0;
  std::uint32_t depth = 0;
  bool arrayed = false;
  bool multisampled = false;
};

struct Variable {
  std::uint32_t id;
  std::uint32_t pointerType;
  std::uint32_t storage;
};

}  // namespace

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
  std::set<std::uint32_t> blocks;
  std::map<std::uint32_t, ImageType> images;
  std::set<std::uint32_t> floats;                        // OpTypeFloat ids
  std::map<std::uint32_t, std::uint32_t> sampledImages;  // OpTypeSampledImage -> its image type
  std::vector<Variable> variables;
  for (const spirv::Instruction& inst : module.instructions) {
    const auto& ops = inst.operands;
    if (inst.opcode == spv::OpName && ops.size() >= 2) {
      if (auto name = spirv::literalString(ops, 1)) names[ops[0]] = *name;
    } else if (inst.opcode == spv::OpTypePointer && ops.size() >= 3) {
      pointees[ops[0]] = ops[2];
    } else if (inst.opcode == spv::OpTypeFloat && ops.size() >= 1) {
      floats.insert(ops[0]);
    } else if (inst.opcode == spv::OpTypeImage && ops.size() >= 6) {
      images[ops[0]] = {ops[1], ops[2], ops[3], ops[4] != 0, ops[5] != 0};
    } else if (inst.opcode == spv::OpTypeSampledImage && ops.size() >= 2) {
      sampledImages[ops[0]] = ops[1];
    } else if (inst.opcode == spv::OpDecorate && ops.size() >= 2) {
      if (ops[1] == spv::DecorationDescriptorSet && ops.size() >= 3) sets[ops[0]] = ops[2];
      if (ops[1] == spv::DecorationBinding && ops.size() >= 3) bindings[ops[0]] = ops[2];
      if (ops[1] == spv::DecorationBlock) blocks.insert(ops[0]);
    } else if (inst.opcode == spv::OpVariable && ops.size() >= 3) {
      const std::uint32_t storage = ops[2];
      if (storage == spv::StorageClassUniform || storage == spv::StorageClassUniformConstant ||
          storage == spv::StorageClassStorageBuffer) {
        variables.push_back({ops[1], ops[0], storage});
      }
    }
  }
  for (const Variable& variable : variables) {
    const std::uint32_t pointee = pointees[variable.pointerType];
    DescriptorResource resource;
    resource.name = names[variable.id];
    if (resource.name.empty()) resource.name = names[pointee];
    resource.variableId = variable.id;
    resource.set = sets[variable.id];
    resource.binding = bindings[variable.id];
    if (variable.storage == spv::StorageClassUniform && blocks.count(pointee)) {
      resource.kind = DescriptorKind::UniformBuffer;
    } else if (variable.storage == spv::StorageClassUniformConstant &&
               sampledImages.count(pointee)) {
      resource.kind = DescriptorKind::CombinedImageSampler;
      const ImageType image = images[sampledImages[pointee]];
      resource.cube = image.dim == spv::DimCube && !image.arrayed;
      resource.plain2D = image.dim == spv::Dim2D && !image.arrayed && !image.multisampled &&
                         image.depth == 0 && floats.count(image.sampledType) != 0;
    }
    result.resources.push_back(std::move(resource));
  }
  return result;
}

}  // namespace snell::vk
