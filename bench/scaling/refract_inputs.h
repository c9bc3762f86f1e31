#pragma once
// The refract() inputs of the scaling and pipeline benchmarks: unit normals
// in every direction, unit incident vectors against them (dot(I, N) < 0)
// and eta in [0.6, 1.6], so air-to-glass, glass-to-air and total internal
// reflection all occur. The same seed gives the same inputs.
#include <array>
#include <cmath>
#include <random>

namespace snell::bench {

using Vec3 = std::array<float, 3>;

struct RefractInput {
  Vec3 I;
  Vec3 N;
  float eta;
};

class RefractInputs {
 public:
  explicit RefractInputs(unsigned long long seed) : random_(seed) {}

  RefractInput next() {
    const Vec3 n = unitVector();
    Vec3 v = unitVector();
    const float along = v[0] * n[0] + v[1] * n[1] + v[2] * n[2];
    if (along > 0) v = {-v[0], -v[1], -v[2]};  // incident: heading into the surface
    return {v, n, eta_(random_)};
  }

 private:
  Vec3 unitVector() {
    // A new distribution each time (none of its spare values carried over):
    // the inputs stay those of the lines measured before.
    std::normal_distribution<float> normal;
    for (;;) {
      const Vec3 v{normal(random_), normal(random_), normal(random_)};
      const float length = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
      if (length > 1e-3f) return {v[0] / length, v[1] / length, v[2] / length};
    }
  }

  std::mt19937_64 random_;
  std::uniform_real_distribution<float> eta_{0.6f, 1.6f};
};

}  // namespace snell::bench
