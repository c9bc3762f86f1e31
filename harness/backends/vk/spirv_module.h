#pragma once
// A bounds-checked view of a SPIR-V binary, just enough for the post-passes
// and resource queries in this folder. Parsing never trusts a word count:
// a malformed module yields an error string, never an out-of-range read.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace snell::vk::spirv {

constexpr std::size_t kHeaderWords = 5;

struct Instruction {
  std::size_t offset = 0;  // index of the instruction's first word in the module
  std::uint16_t opcode = 0;
  std::span<const std::uint32_t> operands;  // the words after the opcode word
};

struct Module {
  std::vector<Instruction> instructions;  // views into the parsed words
  std::string error;                      // empty when the module parsed
};

// The words must outlive the returned instructions.
Module parseModule(std::span<const std::uint32_t> words);

// Decodes a nul-terminated literal string starting at operands[first].
// `wordsUsed` (if given) receives how many words it occupied.
std::optional<std::string> literalString(std::span<const std::uint32_t> operands, std::size_t first,
                                         std::size_t* wordsUsed = nullptr);

// Appends one instruction (opcode word included) to `out`.
void appendInstruction(std::vector<std::uint32_t>& out, std::uint16_t opcode,
                       std::initializer_list<std::uint32_t> operands);

}  // namespace snell::vk::spirv
