// The SPIR-V transform feedback post-pass. Input: one byte choosing which
// outputs to capture (bit k asks for kNames[k]; bit 7 reverses the order),
// then the module's words. The pass must never throw; on success its layout
// must be the one it documents (tightly packed, in the order asked for).
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "backends/vk/spirv_xfb_pass.h"

namespace {

// The seeds' outputs, an input, a built-in block member and a name no module has.
const char* const kNames[] = {"Reflect", "Refract", "Ratio", "Spare", "MCvertex", "gl_Position", "Missing"};

void check(bool condition) {
  if (!condition) __builtin_trap();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const std::uint8_t select = data[0];
  std::vector<std::string> names;
  for (int k = 0; k < 7; ++k)
    if (select & (1u << k)) names.emplace_back(kNames[k]);
  if (select & 0x80) std::reverse(names.begin(), names.end());

  std::vector<std::uint32_t> words((size - 1) / 4);
  if (!words.empty()) std::memcpy(words.data(), data + 1, words.size() * 4);

  const snell::vk::XfbPassResult result = snell::vk::addTransformFeedback(words, names);
  if (!result.ok()) {
    check(result.spirv.empty());
    return 0;
  }
  check(result.varyings.size() == names.size());
  std::uint32_t offset = 0;
  for (std::size_t i = 0; i < names.size(); ++i) {
    check(result.varyings[i].name == names[i]);
    check(result.varyings[i].components >= 1 && result.varyings[i].components <= 4);
    check(result.varyings[i].offset == offset);
    offset += static_cast<std::uint32_t>(result.varyings[i].components) * 4;
  }
  check(result.stride == offset);
  check(result.spirv.size() > words.size());
  return 0;
}
