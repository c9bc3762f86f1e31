#include "oracle/reference/reference_image.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>

#include "core/errors.h"
#include "oracle/reference/fragment_oracle.h"
#include "oracle/reference/pixel_masks.h"
#include "oracle/reference/rasterizer.h"
#include "oracle/vertex_oracle.h"

namespace snell {
namespace {

constexpr const char* kPositionOutput = "gl_Position";

const OracleVarying& findVarying(const std::string& oracle,
                                 const std::vector<OracleVarying>& varyings,
                                 const std::string& name, int components) {
  for (const OracleVarying& varying : varyings) {
    if (varying.name != name) continue;
    if (varying.components != components)
      throw UsageError(
          fmt::format("oracle '{}': the fragment part reads {} with {} components, "
                      "the vertex part writes {}",
                      oracle, name, components, varying.components));
    return varying;
  }
  throw UsageError(
      fmt::format("oracle '{}': the fragment part reads {}, which the vertex part does not write",
                  oracle, name));
}

void checkCubeMaps(const ReferenceInput& input, const FragmentOracle& fragment) {
  for (const std::string& name : fragment.samplers()) {
    const auto found = input.cubeMaps.find(name);
    if (found == input.cubeMaps.end() || found->second == nullptr)
      throw UsageError(
          fmt::format("oracle '{}': samplerCube {} has no cube map bound", input.oracle, name));
    const CubeMap& map = *found->second;
    const std::size_t texels = static_cast<std::size_t>(map.size) * map.size * 4;
    const bool complete = map.size > 0 && std::all_of(map.faces.begin(), map.faces.end(),
                                                      [&](const std::vector<float>& face) {
                                                        return face.size() == texels;
                                                      });
    if (!complete)
      throw UsageError(fmt::format("oracle '{}': cube map {} is not six {}x{} RGBA faces",
                                   input.oracle, name, map.size, map.size));
  }
}

void checkTextures2D(const ReferenceInput& input, const FragmentOracle& fragment) {
  for (const std::string& name : fragment.samplers2D()) {
    const auto found = input.textures2D.find(name);
    if (found == input.textures2D.end() || found->second == nullptr)
      throw UsageError(
          fmt::format("oracle '{}': sampler2D {} has no 2D texture bound", input.oracle, name));
    const Image& image = *found->second;
    if (image.width <= 0 || image.height <= 0 ||
        image.pixels.size() != static_cast<std::size_t>(image.width) * image.height * 4)
      throw UsageError(fmt::format("oracle '{}': 2D texture {} is not {}x{} RGBA texels",
                                   input.oracle, name, image.width, image.height));
  }
}

void checkUniforms(const ReferenceInput& input, const FragmentOracle& fragment) {
  for (const FragmentUniform& uniform : fragment.uniforms()) {
    const auto found = input.uniforms.find(uniform.name);
    if (found == input.uniforms.end())
      throw UsageError(fmt::format("oracle '{}': the fragment part's uniform {} {} is not set",
                                   input.oracle, glslTypeName(uniform.type), uniform.name));
    const Value& value = found->second;
    if (value.type != uniform.type ||
        value.data.size() != static_cast<std::size_t>(componentCount(uniform.type)))
      throw UsageError(
          fmt::format("oracle '{}': uniform {} is a {} with {} floats, the fragment "
                      "part declares {} {}",
                      input.oracle, uniform.name, glslTypeName(value.type), value.data.size(),
                      glslTypeName(uniform.type), uniform.name));
  }
}

std::vector<ClipPosition> clipPositions(const std::string& oracle,
                                        const std::vector<OracleVarying>& varyings) {
  const OracleVarying& position = findVarying(oracle, varyings, kPositionOutput, 4);
  std::vector<ClipPosition> positions(position.reference.size() / 4);
  for (std::size_t v = 0; v < positions.size(); ++v) {
    const double* p = &position.reference[4 * v];
    positions[v] = {p[0], p[1], p[2], p[3]};
  }
  return positions;
}

// What a covered pixel's fragment part reads: each input interpolated with
// the pixel's weights, and whether the spec leaves any of them undefined at
// one of the triangle's vertices (the interpolated value is then undefined
// too, wherever in the triangle the pixel lies).
class FragmentInputs {
 public:
  FragmentInputs(const std::string& oracle, const FragmentOracle& fragment,
                 const std::vector<OracleVarying>& varyings) {
    for (const FragmentInput& in : fragment.inputs())
      sources_.push_back(&findVarying(oracle, varyings, in.name, in.components));
    std::size_t size = 0;
    for (const OracleVarying* source : sources_) size += source->components;
    values_.resize(size);
  }

  // Returns false when an input is undefined at one of the vertices.
  bool gather(const std::array<std::uint32_t, 3>& vertices, const std::array<double, 3>& weights) {
    bool defined = true;
    std::size_t next = 0;
    for (const OracleVarying* source : sources_) {
      const auto components = static_cast<std::size_t>(source->components);
      for (std::size_t c = 0; c < components; ++c) {
        double value = 0;
        for (int k = 0; k < 3; ++k) {
          const std::size_t at = vertices[k] * components + c;
          value += weights[k] * source->reference[at];
          defined = defined && !source->undefined[at];
        }
        values_[next++] = value;
      }
    }
    return defined;
  }

  std::span<const double> values() const { return values_; }

 private:
  std::vector<const OracleVarying*> sources_;
  std::vector<double> values_;
};

bool finiteColor(const std::array<double, 4>& color) {
  return std::all_of(color.begin(), color.end(), [](double c) { return std::isfinite(c); });
}

}  // namespace

ReferenceImage renderReferenceImage(const ReferenceInput& input) {
  const std::unique_ptr<FragmentOracle> registeredFragment =
      input.fragment ? nullptr : makeFragmentOracle(input.oracle);
  const std::unique_ptr<VertexOracle> registeredVertex =
      input.vertex ? nullptr : makeVertexOracle(input.oracle);
  const FragmentOracle* fragment = input.fragment ? input.fragment : registeredFragment.get();
  const VertexOracle* vertex = input.vertex ? input.vertex : registeredVertex.get();
  checkCubeMaps(input, *fragment);
  checkTextures2D(input, *fragment);
  checkUniforms(input, *fragment);
  const FragmentBindings bindings{input.cubeMaps, input.textures2D, input.uniforms};
  const std::vector<OracleVarying> varyings =
      vertex->evaluate({input.uniforms, input.constants, input.attributes, input.vertexCount});
  FragmentInputs inputs(input.oracle, *fragment, varyings);
  const Visibility visibility = rasterize(clipPositions(input.oracle, varyings), input.indices,
                                          {input.width, input.height, input.cullBackFaces});
  const std::vector<std::uint8_t> silhouette = silhouettePixels(visibility);

  ReferenceImage image;
  image.color = Image(input.width, input.height);
  image.mask.assign(static_cast<std::size_t>(input.width) * input.height, PixelMask::None);
  for (int y = 0; y < input.height; ++y) {
    for (int x = 0; x < input.width; ++x) {
      const std::size_t pixel = static_cast<std::size_t>(y) * input.width + x;
      float* out = image.color.at(x, y);
      if (silhouette[pixel]) image.mask[pixel] = PixelMask::Silhouette;
      if (!visibility.covered(x, y)) {
        std::copy(input.clearColor.begin(), input.clearColor.end(), out);
        continue;
      }
      const std::size_t first = 3 * static_cast<std::size_t>(visibility.triangle[pixel]);
      const std::array<std::uint32_t, 3> vertices = {input.indices[first], input.indices[first + 1],
                                                     input.indices[first + 2]};
      const bool inputsDefined = inputs.gather(vertices, visibility.weights[pixel]);
      const FragmentResult result = fragment->shade(inputs.values(), bindings);
      const bool finite = finiteColor(result.color);
      for (int c = 0; c < 4; ++c) out[c] = finite ? static_cast<float>(result.color[c]) : 0.0f;
      // One reason per pixel, the strongest first: an undefined result is
      // reported as non-portable whatever else holds there; a silhouette
      // pixel may not be covered by an implementation at all; a face edge
      // matters only where the pixel is otherwise compared.
      if (!inputsDefined || result.undefined || !finite) {
        image.mask[pixel] = PixelMask::Undefined;
      } else if (result.faceEdge && image.mask[pixel] == PixelMask::None) {
        image.mask[pixel] = PixelMask::FaceEdge;
      }
    }
  }
  return image;
}

}  // namespace snell
