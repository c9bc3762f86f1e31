#include "backends/vk/spirv_output_locations.h"

#include <glslang/SPIRV/spirv.hpp>
#include <map>
#include <set>

#include "backends/vk/spirv_module.h"
#include "core/fragment_probes.h"

namespace snell::vk {

OutputLocationResult assignProbeOutputLocations(std::span<const std::uint32_t> spirv) {
  OutputLocationResult result;
  const spirv::Module module = spirv::parseModule(spirv);
  if (!module.error.empty()) {
    result.error = module.error;
    return result;
  }
  std::map<std::uint32_t, std::string> names;
  std::set<std::uint32_t> outputs, builtIns;
  std::map<std::uint32_t, std::size_t> locationWord;  // variable -> index of its Location literal
  for (const spirv::Instruction& inst : module.instructions) {
    const auto& ops = inst.operands;
    if (inst.opcode == spv::OpName && ops.size() >= 2) {
      if (auto name = spirv::literalString(ops, 1)) names[ops[0]] = *name;
    } else if (inst.opcode == spv::OpVariable && ops.size() >= 3 &&
               ops[2] == spv::StorageClassOutput) {
      outputs.insert(ops[1]);
    } else if (inst.opcode == spv::OpDecorate && ops.size() >= 2) {
      if (ops[1] == spv::DecorationBuiltIn) builtIns.insert(ops[0]);
      // The literal is the instruction's fourth word: opcode, target, decoration, value.
      if (ops[1] == spv::DecorationLocation && ops.size() >= 3) locationWord[ops[0]] = inst.offset + 3;
    }
  }
  std::vector<std::uint32_t> words(spirv.begin(), spirv.end());
  std::vector<std::uint32_t> listingOutputs;
  for (const std::uint32_t variable : outputs) {
    if (builtIns.count(variable)) continue;
    const auto word = locationWord.find(variable);
    const auto name = names.find(variable);
    if (word == locationWord.end() || name == names.end()) {
      result.error = "fragment output %" + std::to_string(variable) +
                     " lacks a Location decoration or a name to place it by";
      return result;
    }
    const std::optional<int> location = probeOutputLocation(name->second);
    if (!location) {
      listingOutputs.push_back(variable);
      continue;
    }
    words[word->second] = static_cast<std::uint32_t>(*location);
  }
  if (listingOutputs.size() > 1) {
    result.error = "the fragment shader declares " + std::to_string(listingOutputs.size()) +
                   " outputs besides the probes; a render reads one";
    return result;
  }
  for (const std::uint32_t variable : listingOutputs) words[locationWord[variable]] = 0;
  result.spirv = std::move(words);
  return result;
}

}  // namespace snell::vk
