#include "backends/vk/spirv_xfb_pass.h"

#include <algorithm>
#include <glslang/SPIRV/spirv.hpp>
#include <map>
#include <optional>
#include <set>

#include "backends/vk/spirv_module.h"

namespace snell::vk {

namespace {

using spirv::Instruction;

// Instructions that SPIR-V's logical layout places before the first type
// declaration; transform feedback decorations go right after the last of them.
bool isPreamble(std::uint16_t opcode) {
  switch (opcode) {
    case spv::OpCapability:
    case spv::OpExtension:
    case spv::OpExtInstImport:
    case spv::OpMemoryModel:
    case spv::OpEntryPoint:
    case spv::OpExecutionMode:
    case spv::OpExecutionModeId:
    case spv::OpString:
    case spv::OpSourceExtension:
    case spv::OpSource:
    case spv::OpSourceContinued:
    case spv::OpName:
    case spv::OpMemberName:
    case spv::OpModuleProcessed:
    case spv::OpDecorate:
    case spv::OpMemberDecorate:
    case spv::OpDecorationGroup:
    case spv::OpGroupDecorate:
    case spv::OpGroupMemberDecorate:
    case spv::OpDecorateId:
    case spv::OpDecorateString:
    case spv::OpMemberDecorateString:
      return true;
    default:
      return false;
  }
}

const char* storageClassName(std::uint32_t storage) {
  switch (storage) {
    case spv::StorageClassInput:
      return "an input";
    case spv::StorageClassOutput:
      return "an output";
    case spv::StorageClassUniform:
      return "a uniform block";
    case spv::StorageClassUniformConstant:
      return "a uniform";
    case spv::StorageClassFunction:
      return "a local variable";
    case spv::StorageClassPrivate:
      return "a global variable";
    default:
      return "a non-output variable";
  }
}

struct Variable {
  std::uint32_t pointerType = 0;
  std::uint32_t storage = 0;
};

// What the pass needs to know about the module, gathered in one walk.
struct ModuleFacts {
  std::multimap<std::string, std::uint32_t> idsByName;
  std::map<std::uint32_t, Variable> variables;
  std::map<std::uint32_t, std::pair<std::uint32_t, std::uint32_t>>
      pointers;                                        // id -> storage, pointee
  std::map<std::uint32_t, std::uint32_t> floatWidths;  // OpTypeFloat id -> width
  std::map<std::uint32_t, std::pair<std::uint32_t, std::uint32_t>>
      vectors;                           // id -> component, count
  std::set<std::uint32_t> xfbDecorated;  // ids already carrying an Offset/Xfb decoration
  std::optional<std::uint32_t> vertexEntry;
  std::set<std::uint32_t> entryInterface;
  int vertexEntries = 0;
  bool hasXfbCapability = false;
  bool hasXfbMode = false;
  std::size_t capabilityEnd = 0;  // word offsets where each insertion goes
  std::size_t modeEnd = 0;
  std::size_t decorationEnd = 0;
  bool sawBody = false;
};

std::string gatherFacts(const spirv::Module& module, ModuleFacts& facts) {
  for (const Instruction& inst : module.instructions) {
    const auto& ops = inst.operands;
    const std::size_t end = inst.offset + ops.size() + 1;
    if (!isPreamble(inst.opcode) && !facts.sawBody) {
      facts.sawBody = true;
      facts.decorationEnd = inst.offset;
    }
    if (isPreamble(inst.opcode) && facts.sawBody) {
      return "SPIR-V instruction " + std::to_string(inst.opcode) + " at word " +
             std::to_string(inst.offset) + " is out of the logical layout order";
    }
    auto need = [&](std::size_t n) { return ops.size() >= n; };
    switch (inst.opcode) {
      case spv::OpCapability:
        if (!need(1)) return "truncated OpCapability";
        if (ops[0] == spv::CapabilityTransformFeedback) facts.hasXfbCapability = true;
        facts.capabilityEnd = end;
        break;
      case spv::OpEntryPoint: {
        if (!need(3)) return "truncated OpEntryPoint";
        std::size_t nameWords = 0;
        if (!spirv::literalString(ops, 2, &nameWords)) return "OpEntryPoint name is not terminated";
        if (ops[0] == spv::ExecutionModelVertex) {
          ++facts.vertexEntries;
          facts.vertexEntry = ops[1];
          facts.entryInterface.insert(ops.begin() + 2 + nameWords, ops.end());
        }
        facts.modeEnd = std::max(facts.modeEnd, end);
        break;
      }
      case spv::OpExecutionMode:
      case spv::OpExecutionModeId:
        if (!need(2)) return "truncated OpExecutionMode";
        if (ops[1] == spv::ExecutionModeXfb) facts.hasXfbMode = true;
        facts.modeEnd = std::max(facts.modeEnd, end);
        break;
      case spv::OpName: {
        if (!need(2)) return "truncated OpName";
        auto name = spirv::literalString(ops, 1);
        if (!name) return "OpName string is not terminated";
        facts.idsByName.emplace(*name, ops[0]);
        break;
      }
      case spv::OpDecorate:
        if (!need(2)) return "truncated OpDecorate";
        if (ops[1] == spv::DecorationOffset || ops[1] == spv::DecorationXfbBuffer ||
            ops[1] == spv::DecorationXfbStride) {
          facts.xfbDecorated.insert(ops[0]);
        }
        break;
      case spv::OpTypeFloat:
        if (!need(2)) return "truncated OpTypeFloat";
        facts.floatWidths[ops[0]] = ops[1];
        break;
      case spv::OpTypeVector:
        if (!need(3)) return "truncated OpTypeVector";
        facts.vectors[ops[0]] = {ops[1], ops[2]};
        break;
      case spv::OpTypePointer:
        if (!need(3)) return "truncated OpTypePointer";
        facts.pointers[ops[0]] = {ops[1], ops[2]};
        break;
      case spv::OpVariable:
        if (!need(3)) return "truncated OpVariable";
        facts.variables[ops[1]] = {ops[0], ops[2]};
        break;
      default:
        break;
    }
  }
  if (!facts.sawBody) return "SPIR-V module has no types or functions";
  if (facts.vertexEntries != 1) {
    return "SPIR-V module has " + std::to_string(facts.vertexEntries) +
           " vertex entry points; exactly one is needed";
  }
  if (facts.capabilityEnd == 0) return "SPIR-V module declares no capabilities";
  if (facts.capabilityEnd > facts.modeEnd || facts.modeEnd > facts.decorationEnd) {
    return "SPIR-V module sections are out of order";
  }
  return {};
}

// Components of a 32-bit float scalar or vector, or 0 for any other type.
int floatComponents(const ModuleFacts& facts, std::uint32_t type) {
  if (auto f = facts.floatWidths.find(type); f != facts.floatWidths.end())
    return f->second == 32 ? 1 : 0;
  auto v = facts.vectors.find(type);
  if (v == facts.vectors.end()) return 0;
  auto f = facts.floatWidths.find(v->second.first);
  if (f == facts.floatWidths.end() || f->second != 32) return 0;
  const std::uint32_t count = v->second.second;
  return count >= 2 && count <= 4 ? static_cast<int>(count) : 0;
}

// Finds the Output variable called `name`, or says why there is none.
std::string findOutput(const ModuleFacts& facts, const std::string& name, std::uint32_t& id) {
  std::optional<std::uint32_t> found;
  const char* otherKind = nullptr;
  auto [first, last] = facts.idsByName.equal_range(name);
  for (auto it = first; it != last; ++it) {
    auto var = facts.variables.find(it->second);
    if (var == facts.variables.end()) continue;
    if (var->second.storage != spv::StorageClassOutput) {
      otherKind = storageClassName(var->second.storage);
      continue;
    }
    if (found && *found != it->second) return "'" + name + "' names more than one output variable";
    found = it->second;
  }
  if (found) {
    id = *found;
    return {};
  }
  if (otherKind) return "'" + name + "' is " + otherKind + ", not a vertex output";
  return "'" + name + "' is not a vertex output of this shader";
}

}  // namespace

XfbPassResult addTransformFeedback(std::span<const std::uint32_t> words,
                                   std::span<const std::string> varyings) {
  XfbPassResult result;
  const spirv::Module module = spirv::parseModule(words);
  if (!module.error.empty()) {
    result.error = module.error;
    return result;
  }
  ModuleFacts facts;
  if (std::string error = gatherFacts(module, facts); !error.empty()) {
    result.error = error;
    return result;
  }
  if (varyings.empty()) {
    result.error = "no outputs to capture";
    return result;
  }
  if (facts.hasXfbMode) {
    result.error = "SPIR-V module already declares transform feedback";
    return result;
  }

  std::vector<std::uint32_t> ids;
  std::set<std::string> seen;
  for (const std::string& name : varyings) {
    if (!seen.insert(name).second) {
      result.error = "'" + name + "' is asked for twice";
      return result;
    }
    std::uint32_t id = 0;
    if (std::string error = findOutput(facts, name, id); !error.empty()) {
      result.error = error;
      return result;
    }
    if (facts.xfbDecorated.count(id)) {
      result.error = "'" + name + "' already has an Offset or Xfb decoration";
      return result;
    }
    if (!facts.entryInterface.count(id)) {
      result.error = "'" + name + "' is not in the vertex entry point's interface";
      return result;
    }
    auto pointer = facts.pointers.find(facts.variables.at(id).pointerType);
    const int components =
        pointer == facts.pointers.end() ? 0 : floatComponents(facts, pointer->second.second);
    if (components == 0) {
      result.error = "'" + name + "' is not a float scalar or vector; only those can be captured";
      return result;
    }
    result.varyings.push_back({name, components, result.stride});
    result.stride += static_cast<std::uint32_t>(components) * 4;
    ids.push_back(id);
  }

  std::vector<std::uint32_t>& out = result.spirv;
  out.reserve(words.size() + 16 * ids.size() + 8);
  out.insert(out.end(), words.begin(), words.begin() + facts.capabilityEnd);
  if (!facts.hasXfbCapability) {
    spirv::appendInstruction(out, spv::OpCapability, {spv::CapabilityTransformFeedback});
  }
  out.insert(out.end(), words.begin() + facts.capabilityEnd, words.begin() + facts.modeEnd);
  spirv::appendInstruction(out, spv::OpExecutionMode, {*facts.vertexEntry, spv::ExecutionModeXfb});
  out.insert(out.end(), words.begin() + facts.modeEnd, words.begin() + facts.decorationEnd);
  for (std::size_t i = 0; i < ids.size(); ++i) {
    spirv::appendInstruction(out, spv::OpDecorate, {ids[i], spv::DecorationXfbBuffer, 0});
    spirv::appendInstruction(out, spv::OpDecorate,
                             {ids[i], spv::DecorationXfbStride, result.stride});
    spirv::appendInstruction(out, spv::OpDecorate,
                             {ids[i], spv::DecorationOffset, result.varyings[i].offset});
  }
  out.insert(out.end(), words.begin() + facts.decorationEnd, words.end());
  return result;
}

}  // namespace snell::vk
