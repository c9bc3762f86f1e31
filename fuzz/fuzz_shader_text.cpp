// The two text transforms that rewrite a listing before it is compiled: the
// fragment probe adapter and the Vulkan legacy adapter; and the reader of
// main()'s statements that `snell init` drafts captures from. The input's first
// byte picks the probe's line, type and output style; the rest is the
// source. The probe adapter may throw UsageError for a line it cannot use;
// anything else (a crash, another exception, a sanitizer report, a line
// added or lost) is a finding.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "backends/vk/legacy_adapter.h"
#include "core/errors.h"
#include "core/fragment_probes.h"
#include "core/glsl_statements.h"

namespace {

std::size_t lineBreaks(const std::string& text) {
  std::size_t n = 0;
  for (char c : text) n += c == '\n';
  return n;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::uint8_t control = data[0];
  const std::string source(reinterpret_cast<const char*>(data + 1), size - 1);

  const snell::LegacyStage stage =
      control & 1 ? snell::LegacyStage::Fragment : snell::LegacyStage::Vertex;
  const snell::LegacyAdapted adapted = snell::adaptLegacyForVulkan(source, stage);
  // The prologue adds lines of its own, never fewer than the source had.
  if (lineBreaks(adapted.text) < lineBreaks(source)) std::abort();

  static const snell::ValueType kTypes[] = {snell::ValueType::Float, snell::ValueType::Vec2,
                                            snell::ValueType::Vec3};
  const snell::FragmentProbe probe{"x", kTypes[(control >> 1) % 3], 1 + (control >> 3)};
  const snell::ProbeOutputStyle style =
      control & 4 ? snell::ProbeOutputStyle::FragData : snell::ProbeOutputStyle::Outputs;
  try {
    const std::string probed = snell::insertFragmentProbes(source, "fuzz.frag", {probe}, style);
    // Writes are appended to existing lines: the line count never changes.
    if (lineBreaks(probed) != lineBreaks(source)) std::abort();
  } catch (const snell::UsageError&) {
  }
  // Every statement lies within the source, in order, ending where it starts or later.
  int previous = 0;
  for (const snell::GlslStatement& s : snell::mainStatements(source)) {
    const int last = static_cast<int>(lineBreaks(source)) + 1;
    if (s.firstLine < previous || s.firstLine > s.lastLine || s.lastLine > last || s.depth < 0)
      std::abort();
    previous = s.lastLine;
  }
  return 0;
}
