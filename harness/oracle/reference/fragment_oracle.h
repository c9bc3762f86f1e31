#pragma once
// What the reference renderer asks of a drawing listing's fragment part:
// given the interpolated vertex outputs it reads, the bound textures and
// its loose uniforms,
// the colour the listing writes (in double) and whether the pixel must be
// left out of the image gate.
#include <array>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "core/cube_map.h"
#include "core/image.h"
#include "core/values.h"

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
using Texture2DBindings = std::map<std::string, const Image*>;

// What is the same for every fragment of a draw.
struct FragmentBindings {
  CubeMapBindings cubeMaps;      // samplerCube uniforms by GLSL name
  Texture2DBindings textures2D;  // sampler2D uniforms by GLSL name
  UniformMap uniforms;           // loose uniforms by GLSL name, as the backends got them
};

struct FragmentUniform {
  std::string name;
  ValueType type = ValueType::Float;
};

class FragmentOracle {
 public:
  virtual ~FragmentOracle() = default;
  // The inputs it reads, in the order shade() expects them packed.
  virtual std::vector<FragmentInput> inputs() const = 0;
  // The samplerCube uniforms it looks up, by GLSL name.
  virtual std::vector<std::string> samplers() const = 0;
  // The sampler2D uniforms it looks up, by GLSL name.
  virtual std::vector<std::string> samplers2D() const { return {}; }
  // The loose uniforms it reads (a float, a vector or a matrix each).
  virtual std::vector<FragmentUniform> uniforms() const { return {}; }
  // One fragment. `inputs` holds inputs() packed in order; `bindings` binds
  // every name samplers(), samplers2D() and uniforms() give, with the
  // declared types (the caller checks).
  virtual FragmentResult shade(std::span<const double> inputs,
                               const FragmentBindings& bindings) const = 0;
  // A listing that reads cube maps and interpolated inputs only.
  FragmentResult shade(std::span<const double> inputs, const CubeMapBindings& cubeMaps) const {
    return shade(inputs, FragmentBindings{cubeMaps, {}, {}});
  }
};

// The fragment part registered under `name` (the manifest's `oracle`, the
// same name as the vertex part); throws UsageError when the listing has none.
std::unique_ptr<FragmentOracle> makeFragmentOracle(const std::string& name);

}  // namespace snell
