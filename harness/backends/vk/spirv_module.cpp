#include "backends/vk/spirv_module.h"

namespace snell::vk::spirv {

namespace {
constexpr std::uint32_t kMagic = 0x07230203;
}

Module parseModule(std::span<const std::uint32_t> words) {
  Module module;
  if (words.size() < kHeaderWords) {
    module.error = "SPIR-V module is shorter than its 5-word header";
    return module;
  }
  if (words[0] != kMagic) {
    module.error = "not a SPIR-V module (bad magic number)";
    return module;
  }
  std::size_t at = kHeaderWords;
  while (at < words.size()) {
    const std::uint32_t first = words[at];
    const std::size_t wordCount = first >> 16;
    const auto opcode = static_cast<std::uint16_t>(first & 0xffffu);
    if (wordCount == 0) {
      module.error = "SPIR-V instruction at word " + std::to_string(at) + " has a word count of 0";
      return module;
    }
    if (wordCount > words.size() - at) {
      module.error = "SPIR-V instruction at word " + std::to_string(at) + " (opcode " +
                     std::to_string(opcode) + ") runs past the end of the module";
      return module;
    }
    module.instructions.push_back({at, opcode, words.subspan(at + 1, wordCount - 1)});
    at += wordCount;
  }
  return module;
}

std::optional<std::string> literalString(std::span<const std::uint32_t> operands, std::size_t first,
                                         std::size_t* wordsUsed) {
  std::string text;
  for (std::size_t i = first; i < operands.size(); ++i) {
    for (int byte = 0; byte < 4; ++byte) {
      // SPIR-V packs string bytes little-end first within each word.
      const char c = static_cast<char>((operands[i] >> (8 * byte)) & 0xffu);
      if (c == '\0') {
        if (wordsUsed) *wordsUsed = i - first + 1;
        return text;
      }
      text.push_back(c);
    }
  }
  return std::nullopt;
}

void appendInstruction(std::vector<std::uint32_t>& out, std::uint16_t opcode,
                       std::initializer_list<std::uint32_t> operands) {
  const auto wordCount = static_cast<std::uint32_t>(operands.size() + 1);
  out.push_back((wordCount << 16) | opcode);
  out.insert(out.end(), operands.begin(), operands.end());
}

}  // namespace snell::vk::spirv
