// Writes COUNT refract() calls as `snell eval` JSON Lines: unit normals in
// every direction, unit incident vectors against them (dot(I, N) < 0) and
// eta in [0.6, 1.6], so air-to-glass, glass-to-air and total internal
// reflection all occur. The same COUNT and SEED give the same lines.
// Usage: snell_refract_vectors COUNT [SEED]   (COUNT may be written 1e6)
#include <fmt/format.h>

#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>

namespace {

using Vec3 = std::array<float, 3>;

Vec3 unitVector(std::mt19937_64& random) {
  std::normal_distribution<float> normal;
  for (;;) {
    const Vec3 v{normal(random), normal(random), normal(random)};
    const float length = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (length > 1e-3f) return {v[0] / length, v[1] / length, v[2] / length};
  }
}

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
    fmt::print(stderr,
               "usage: snell_refract_vectors COUNT [SEED]: COUNT a whole number of lines from 1 "
               "to 1e12 (1e6 is accepted), SEED a whole number\n");
    return 2;
  }
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<float> eta(0.6f, 1.6f);
  fmt::memory_buffer out;
  for (unsigned long long i = 0; i < count; ++i) {
    const Vec3 n = unitVector(random);
    Vec3 v = unitVector(random);
    const float along = v[0] * n[0] + v[1] * n[1] + v[2] * n[2];
    if (along > 0) v = {-v[0], -v[1], -v[2]};  // incident: heading into the surface
    fmt::format_to(std::back_inserter(out),
                   "{{\"fn\":\"refract\",\"I\":[{},{},{}],\"N\":[{},{},{}],\"eta\":{}}}\n", v[0],
                   v[1], v[2], n[0], n[1], n[2], eta(random));
    if (out.size() > (1 << 20)) {
      if (std::fwrite(out.data(), 1, out.size(), stdout) != out.size()) return 1;
      out.clear();
    }
  }
  if (std::fwrite(out.data(), 1, out.size(), stdout) != out.size()) return 1;
  return std::fflush(stdout) == 0 ? 0 : 1;
}
