#include "vk_test_support.h"

#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

namespace snell::vktest {

namespace {

constexpr std::uint16_t kOpName = 5;
constexpr std::uint16_t kOpMemberName = 6;
constexpr std::uint16_t kOpMemberDecorate = 72;
constexpr std::uint16_t kOpTypePointer = 32;
constexpr std::uint16_t kOpVariable = 59;
constexpr std::uint16_t kOpDecorate = 71;
constexpr std::uint32_t kDecorationBinding = 33;
constexpr std::uint32_t kDecorationDescriptorSet = 34;

std::string stringAt(const Words& instruction, std::size_t first) {
  std::string text;
  for (std::size_t i = first; i < instruction.size(); ++i) {
    for (int byte = 0; byte < 4; ++byte) {
      const char c = static_cast<char>((instruction[i] >> (8 * byte)) & 0xff);
      if (c == '\0') return text;
      text.push_back(c);
    }
  }
  return text;
}

}  // namespace

std::string readSourceFile(const std::string& relativePath) {
  const std::string path = std::string(SNELL_SOURCE_ROOT) + "/" + relativePath;
  std::ifstream file(path, std::ios::binary);
  if (!file) throw std::runtime_error("cannot read " + path);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

std::vector<Words> instructionsOf(const Words& module) {
  std::vector<Words> instructions;
  std::size_t at = 5;
  while (at < module.size()) {
    const std::size_t count = module[at] >> 16;
    if (count == 0 || at + count > module.size())
      throw std::runtime_error("malformed module in test");
    instructions.emplace_back(module.begin() + at, module.begin() + at + count);
    at += count;
  }
  return instructions;
}

std::optional<std::uint32_t> idNamed(const Words& module, const std::string& name) {
  for (const Words& inst : instructionsOf(module)) {
    if ((inst[0] & 0xffff) == kOpName && stringAt(inst, 2) == name) return inst[1];
  }
  return std::nullopt;
}

std::vector<std::pair<std::string, Words>> memberDecorations(const Words& module,
                                                             const std::string& structName) {
  const std::optional<std::uint32_t> structId = idNamed(module, structName);
  std::map<std::uint32_t, std::string> memberNames;
  std::vector<std::pair<std::string, Words>> decorations;
  if (!structId) return decorations;
  for (const Words& inst : instructionsOf(module)) {
    const std::uint16_t opcode = inst[0] & 0xffff;
    if (opcode == kOpMemberName && inst[1] == *structId) memberNames[inst[2]] = stringAt(inst, 3);
    if (opcode == kOpMemberDecorate && inst[1] == *structId) {
      decorations.emplace_back(memberNames[inst[2]], Words(inst.begin() + 2, inst.end()));
    }
  }
  return decorations;
}

std::optional<Slot> descriptorSlot(const Words& module, const std::string& name) {
  const std::optional<std::uint32_t> named = idNamed(module, name);
  if (!named) return std::nullopt;
  std::optional<std::uint32_t> variable;
  std::map<std::uint32_t, std::uint32_t> pointees;
  for (const Words& inst : instructionsOf(module)) {
    const std::uint16_t opcode = inst[0] & 0xffff;
    if (opcode == kOpTypePointer) pointees[inst[1]] = inst[3];
    if (opcode == kOpVariable && (inst[2] == *named || pointees[inst[1]] == *named))
      variable = inst[2];
  }
  if (!variable) return std::nullopt;
  Slot slot;
  int found = 0;
  for (const Words& inst : instructionsOf(module)) {
    if ((inst[0] & 0xffff) != kOpDecorate || inst[1] != *variable || inst.size() < 4) continue;
    if (inst[2] == kDecorationDescriptorSet) {
      slot.set = inst[3];
      ++found;
    }
    if (inst[2] == kDecorationBinding) {
      slot.binding = inst[3];
      ++found;
    }
  }
  if (found != 2) return std::nullopt;
  return slot;
}

ProgramSource vertexProgram(const std::string& source, const std::string& path) {
  ProgramSource program;
  program.vertex = source;
  program.vertexPath = path;
  return program;
}

}  // namespace snell::vktest
