#pragma once
// Hand-built draws for the reference renderer tests: the bindings of
// Listing 14.1 (or 14.3) for a camera at the eye-space origin looking down
// -z, meshes with counter-clockwise front faces, and cube maps whose
// colours say where a lookup went.
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <vector>

#include "core/camera_math.h"
#include "core/cube_map.h"
#include "core/values.h"
#include "oracle/reference/reference_image.h"

namespace snell::test {

// A face colour per cube face (+X, -X, +Y, -Y, +Z, -Z), all different in
// every pair of channels that a mix could confuse.
inline constexpr std::array<std::array<float, 3>, 6> kFaceColors = {{
    {1, 0, 0},  // +X
    {0, 1, 1},  // -X
    {0, 1, 0},  // +Y
    {1, 0, 1},  // -Y
    {0, 0, 1},  // +Z
    {1, 1, 0},  // -Z
}};

inline CubeMap uniformCubeMap(int size, const std::array<std::array<float, 3>, 6>& colors,
                              CubeFilter filter = CubeFilter::Linear, bool seamless = true) {
  CubeMap map;
  map.size = size;
  map.filter = filter;
  map.seamless = seamless;
  for (int face = 0; face < 6; ++face) {
    for (int texel = 0; texel < size * size; ++texel)
      map.faces[face].insert(map.faces[face].end(),
                             {colors[face][0], colors[face][1], colors[face][2], 1.0f});
  }
  return map;
}

inline CubeMap faceColoredCubeMap(int size, CubeFilter filter = CubeFilter::Linear,
                                  bool seamless = true) {
  return uniformCubeMap(size, kFaceColors, filter, seamless);
}

inline CubeMap constantCubeMap(const std::array<float, 3>& color) {
  return uniformCubeMap(2, {color, color, color, color, color, color});
}

// Every channel the same smooth ramp across each face, different per face:
// a small change of lookup direction changes every channel a little.
inline CubeMap gradientCubeMap(int size) {
  CubeMap map;
  map.size = size;
  for (int face = 0; face < 6; ++face)
    for (int j = 0; j < size; ++j)
      for (int i = 0; i < size; ++i) {
        const float value = (face + (i + 0.5f) / size + (j + 0.5f) / size) / 8.0f;
        map.faces[face].insert(map.faces[face].end(), {value, value, value, 1.0f});
      }
  return map;
}

// The face whose major axis a direction has, by the largest magnitude.
inline int majorFace(const std::array<double, 3>& d) {
  int axis = 0;
  for (int k = 1; k < 3; ++k)
    if (std::fabs(d[k]) > std::fabs(d[axis])) axis = k;
  return 2 * axis + (d[axis] < 0 ? 1 : 0);
}

struct Draw {
  // Listing 14.1's names; chromatic() renames the inputs for Listing 14.3.
  std::string oracle = "orange_book_fresnel";
  std::string vertexName = "MCvertex";
  std::string normalName = "MCnormal";
  UniformMap uniforms;
  ConstantMap constants{{"Eta", 0.66}, {"FresnelPower", 5.0}};
  AttributeMap attributes;
  std::vector<std::uint32_t> indices;
  std::size_t vertexCount = 0;
  CubeMap environment = faceColoredCubeMap(16);

  Draw() { setCamera(identity4(), identity4()); }

  void setCamera(const Mat4d& modelView, const Mat4d& projection) {
    uniforms["MVMatrix"] = toMat4Value(modelView);
    uniforms["MVPMatrix"] = toMat4Value(multiply(projection, modelView));
    uniforms["NormalMatrix"] = normalMatrixValue(modelView);
    uniforms["TextureMatrix"] = toMat4Value(identity4());
  }

  std::uint32_t addVertex(const std::array<double, 4>& position,
                          const std::array<double, 3>& normal) {
    AttributeStream& p = attributes[vertexName];
    AttributeStream& n = attributes[normalName];
    p.name = vertexName;
    p.components = 4;
    n.name = normalName;
    n.components = 3;
    for (double c : position) p.data.push_back(static_cast<float>(c));
    for (double c : normal) n.data.push_back(static_cast<float>(c));
    return static_cast<std::uint32_t>(vertexCount++);
  }

  void addTriangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    indices.insert(indices.end(), {a, b, c});
  }

  // A unit-radius sphere about `centre` (model space = eye space), latitude
  // and longitude, counter-clockwise seen from outside.
  void addSphere(const std::array<double, 3>& centre, int stacks, int slices) {
    const std::uint32_t first = static_cast<std::uint32_t>(vertexCount);
    for (int stack = 0; stack <= stacks; ++stack) {
      const double theta = std::numbers::pi * stack / stacks;
      for (int slice = 0; slice <= slices; ++slice) {
        const double phi = 2 * std::numbers::pi * slice / slices;
        const std::array<double, 3> n = {std::sin(theta) * std::cos(phi), std::cos(theta),
                                         std::sin(theta) * std::sin(phi)};
        addVertex({centre[0] + n[0], centre[1] + n[1], centre[2] + n[2], 1.0}, n);
      }
    }
    auto at = [&](int stack, int slice) {
      return first + static_cast<std::uint32_t>(stack * (slices + 1) + slice);
    };
    for (int stack = 0; stack < stacks; ++stack) {
      for (int slice = 0; slice < slices; ++slice) {
        const std::uint32_t a = at(stack, slice), b = at(stack + 1, slice),
                            c = at(stack + 1, slice + 1), d = at(stack, slice + 1);
        addTriangle(a, c, b);
        addTriangle(a, d, c);
      }
    }
  }

  // Listing 14.3's interface: same inputs under its names, three etas.
  void useChromatic(double etaR, double etaG, double etaB) {
    oracle = "orange_book_chromatic";
    for (auto [from, to] : {std::pair{vertexName, std::string("MCVertex")},
                            std::pair{normalName, std::string("MCNormal")}}) {
      auto node = attributes.extract(from);
      if (!node.empty()) {
        node.key() = to;
        node.mapped().name = to;
        attributes.insert(std::move(node));
      }
    }
    vertexName = "MCVertex";
    normalName = "MCNormal";
    constants = {{"EtaR", etaR}, {"EtaG", etaG}, {"EtaB", etaB}, {"FresnelPower", 5.0}};
  }

  ReferenceInput input(int width, int height) const {
    return ReferenceInput{oracle,
                          uniforms,
                          constants,
                          attributes,
                          vertexCount,
                          indices,
                          {{"Cubemap", &environment}},
                          width,
                          height,
                          {0, 0, 0, 0},
                          true};
  }
};

// The camera the sphere tests use: eye-space origin, looking down -z.
inline constexpr double kSphereFovy = 40.0 * std::numbers::pi / 180;
inline Mat4d sphereProjection() { return perspective(kSphereFovy, 1.0, 1.0, 10.0); }

}  // namespace snell::test
