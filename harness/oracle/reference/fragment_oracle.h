#pragma once
// What the reference renderer asks of a drawing listing's fragment part:
// given the interpolated vertex outputs it reads and the bound cube maps,
// the colour the listing writes (in double) and whether the pixel must be
// left out of the image gate.
#include <array>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "core/cube_map.h"

namespace snell {

struct FragmentInput {
  std::string name;  // the `in` variable, named as the vertex part's output
  int components = 1;
};

struct FragmentResult {
  std::array<double, 4> color{};
  bool undefined = false;  // a lookup the spec leaves undefined (zero or NaN direction)
  bool faceEdge = false;   // a lookup on a face edge where the filter makes it a step
};

using CubeMapBindings = std::map<std::string, const CubeMap*>;

class FragmentOracle {
 public:
  virtual ~FragmentOracle() = default;
  // The inputs it reads, in the order shade() expects them packed.
  virtual std::vector<FragmentInput> inputs() const = 0;
  // The samplerCube uniforms it looks up, by GLSL name.
  virtual std::vector<std::string> samplers() const = 0;
  // One fragment. `inputs` holds inputs() packed in order; `cubeMaps` binds
  // every name samplers() gives (the caller checks).
  virtual FragmentResult shade(std::span<const double> inputs,
                               const CubeMapBindings& cubeMaps) const = 0;
};

// The fragment part registered under `name` (the manifest's `oracle`, the
// same name as the vertex part); throws UsageError when the listing has none.
std::unique_ptr<FragmentOracle> makeFragmentOracle(const std::string& name);

}  // namespace snell
