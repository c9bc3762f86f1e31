#include "backends/vk/program_descriptors.h"

#include <map>

#include "backends/vk/spirv_descriptor_rebind.h"
#include "core/errors.h"

namespace snell::vk {

namespace {

struct Stage {
  const char* name;
  std::span<const std::uint32_t> spirv;
  bool ProgramDescriptor::*declares;
};

std::vector<DescriptorResource> resourcesOf(const Stage& stage) {
  DescriptorResources found = listDescriptorResources(stage.spirv);
  if (!found.error.empty()) {
    throw SetupError(std::string("cannot read the ") + stage.name + " SPIR-V: " + found.error);
  }
  return std::move(found.resources);
}

// A layout that disagrees with a module is worse than a validation
// message: lavapipe (Mesa 22.3) dies with SIGBUS inside
// vkCreateGraphicsPipelines before the layer's report can be thrown. So a
// binding that two resources claim stops here, as a readable error.
void describeOnce(std::map<std::uint32_t, ProgramDescriptor>& byBinding, const Stage& stage,
                  const DescriptorResource& resource) {
  if (resource.set != 0) {
    throw SetupError(std::string("the rewritten ") + stage.name + " SPIR-V puts '" + resource.name +
                     "' in descriptor set " + std::to_string(resource.set));
  }
  auto [entry, added] = byBinding.try_emplace(resource.binding);
  ProgramDescriptor& descriptor = entry->second;
  if (added) {
    descriptor.name = resource.name;
    descriptor.kind = resource.kind;
    descriptor.cube = resource.cube;
    descriptor.plain2D = resource.plain2D;
    descriptor.binding = resource.binding;
  } else if (descriptor.name != resource.name || descriptor.kind != resource.kind ||
             descriptor.cube != resource.cube || descriptor.plain2D != resource.plain2D) {
    throw SetupError("binding " + std::to_string(resource.binding) + " holds both '" +
                     descriptor.name + "' and, in the " + stage.name + " SPIR-V, '" +
                     resource.name + "'");
  }
  descriptor.*stage.declares = true;
}

}  // namespace

BoundProgram bindProgramDescriptors(std::span<const std::uint32_t> vertexSpirv,
                                    std::span<const std::uint32_t> fragmentSpirv) {
  const Stage stages[] = {{"vertex", vertexSpirv, &ProgramDescriptor::inVertexStage},
                          {"fragment", fragmentSpirv, &ProgramDescriptor::inFragmentStage}};

  std::map<std::string, std::uint32_t> bindingOf;
  std::map<std::string, DescriptorKind> kindOf;
  std::vector<std::uint32_t> rewritten[2];
  for (int s = 0; s < 2; ++s) {
    std::map<std::uint32_t, DescriptorSlot> slots;
    for (const DescriptorResource& resource : resourcesOf(stages[s])) {
      const auto next = static_cast<std::uint32_t>(bindingOf.size());
      const std::uint32_t binding = bindingOf.try_emplace(resource.name, next).first->second;
      const DescriptorKind kind = kindOf.try_emplace(resource.name, resource.kind).first->second;
      if (kind != resource.kind) {
        throw SetupError("'" + resource.name +
                         "' is a different kind of descriptor in the vertex and fragment stages");
      }
      slots[resource.variableId] = {0, binding};
    }
    RebindResult rebound = rebindDescriptors(stages[s].spirv, slots);
    if (!rebound.ok()) {
      throw SetupError(std::string("cannot rewrite the descriptor bindings of the ") +
                       stages[s].name + " SPIR-V: " + rebound.error);
    }
    rewritten[s] = std::move(rebound.spirv);
  }

  BoundProgram bound;
  bound.vertexSpirv = std::move(rewritten[0]);
  bound.fragmentSpirv = std::move(rewritten[1]);
  std::map<std::uint32_t, ProgramDescriptor> byBinding;
  const Stage reread[] = {{"vertex", bound.vertexSpirv, &ProgramDescriptor::inVertexStage},
                          {"fragment", bound.fragmentSpirv, &ProgramDescriptor::inFragmentStage}};
  for (const Stage& stage : reread) {
    for (const DescriptorResource& resource : resourcesOf(stage))
      describeOnce(byBinding, stage, resource);
  }
  for (auto& [binding, descriptor] : byBinding) bound.descriptors.push_back(std::move(descriptor));
  return bound;
}

}  // namespace snell::vk
