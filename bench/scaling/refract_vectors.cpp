// Writes COUNT refract() calls as `snell eval` JSON Lines, from the inputs
// of refract_inputs.h. The same COUNT and SEED give the same lines.
// Usage: snell_refract_vectors COUNT [SEED]   (COUNT may be written 1e6)
#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <string>

#include "core/message.h"
#include "refract_inputs.h"

namespace {

// A whole number of at least 1, written plainly or as 1e6; 0 when it is not.
unsigned long long parseCount(const std::string& text) {
  double value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || !(value >= 1) || value > 1e12 ||
      value != std::floor(value))
    return 0;
  return static_cast<unsigned long long>(value);
}

}  // namespace

int main(int argc, char** argv) {
  const unsigned long long count = argc >= 2 ? parseCount(argv[1]) : 0;
  unsigned long long seed = 1;
  if (argc > 3 || count == 0 ||
      (argc == 3 &&
       std::from_chars(argv[2], argv[2] + std::string(argv[2]).size(), seed).ec != std::errc())) {
    snell::printMessage(stderr,
                        "usage: snell_refract_vectors COUNT [SEED]: COUNT a whole number of lines "
                        "from 1 to 1e12 (1e6 is accepted), SEED a whole number\n");
    return 2;
  }
  snell::bench::RefractInputs inputs(seed);
  fmt::memory_buffer out;
  for (unsigned long long i = 0; i < count; ++i) {
    const auto [v, n, eta] = inputs.next();
    fmt::format_to(std::back_inserter(out),
                   "{{\"fn\":\"refract\",\"I\":[{},{},{}],\"N\":[{},{},{}],\"eta\":{}}}\n", v[0],
                   v[1], v[2], n[0], n[1], n[2], eta);
    if (out.size() > (1 << 20)) {
      if (std::fwrite(out.data(), 1, out.size(), stdout) != out.size()) return 1;
      out.clear();
    }
  }
  if (std::fwrite(out.data(), 1, out.size(), stdout) != out.size()) return 1;
  return std::fflush(stdout) == 0 ? 0 : 1;
}
