#pragma once
// Builders shared by the GL render tests: clip-space triangles, the shaders
// that draw them, and small cube maps with a distinct colour in every texel.
#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "backends/backend.h"
#include "gl_test_jobs.h"

namespace snell::gltest {

using Rgba = std::array<float, 4>;

// Positions go straight to clip space; each vertex carries a flat colour so
// that a triangle's colour reaches the target without interpolation error.
inline const char* const kFlatColourVertex = R"(#version 140
in vec3 position;
in vec4 colour;
flat out vec4 vColour;
void main() {
  vColour = colour;
  gl_Position = vec4(position, 1.0);
}
)";

inline const char* const kFlatColourFragment = R"(#version 140
flat in vec4 vColour;
out vec4 FragColor;
void main() { FragColor = vColour; }
)";

inline ProgramSource program(std::string vertex, std::string fragment,
                             Profile profile = Profile::Core) {
  ProgramSource source = vertexOnly(std::move(vertex), profile);
  source.fragment = std::move(fragment);
  return source;
}

// Triangles for kFlatColourVertex, added to a job one at a time.
struct Triangles {
  std::vector<float> positions;
  std::vector<float> colours;
  std::vector<std::uint32_t> indices;

  Triangles& add(std::array<float, 3> a, std::array<float, 3> b, std::array<float, 3> c,
                 Rgba colour) {
    for (const auto& vertex : {a, b, c}) {
      indices.push_back(static_cast<std::uint32_t>(positions.size() / 3));
      positions.insert(positions.end(), vertex.begin(), vertex.end());
      colours.insert(colours.end(), colour.begin(), colour.end());
    }
    return *this;
  }

  // Two counter-clockwise triangles covering the whole viewport at depth z.
  Triangles& fullScreen(float z, Rgba colour) {
    add({-1, -1, z}, {1, -1, z}, {1, 1, z}, colour);
    return add({-1, -1, z}, {1, 1, z}, {-1, 1, z}, colour);
  }
};

inline RenderJob flatColourJob(const Triangles& triangles, int width, int height) {
  RenderJob job;
  job.program = program(kFlatColourVertex, kFlatColourFragment);
  job.attributes["position"] = attribute("position", 3, triangles.positions);
  job.attributes["colour"] = attribute("colour", 4, triangles.colours);
  job.indices = triangles.indices;
  job.width = width;
  job.height = height;
  return job;
}

inline Rgba pixel(const Image& image, int x, int y) {
  const float* p = image.at(x, y);
  return {p[0], p[1], p[2], p[3]};
}

// How many pixels of the rectangle [x0, x1) x [y0, y1) differ from `expected`.
inline int pixelsOtherThan(const Image& image, Rgba expected, int x0, int y0, int x1, int y1) {
  int differing = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x)
      if (pixel(image, x, y) != expected) ++differing;
  return differing;
}

// A colour no two texels share, none of whose channels 8 bits can hold, so
// a lookup that lands on the wrong texel or goes through an 8-bit texture
// shows.
inline Rgba texelColour(int face, int i, int j) {
  return {0.1f * static_cast<float>(face + 1), 0.01f * static_cast<float>(i + 1),
          0.001f * static_cast<float>(j + 1), 0.3f};
}

inline CubeMap distinctTexelCubeMap(int size, CubeFilter filter) {
  CubeMap map;
  map.size = size;
  map.filter = filter;
  for (int face = 0; face < 6; ++face) {
    auto& data = map.faces[static_cast<std::size_t>(face)];
    for (int j = 0; j < size; ++j)
      for (int i = 0; i < size; ++i) {
        const Rgba colour = texelColour(face, i, j);
        data.insert(data.end(), colour.begin(), colour.end());
      }
  }
  return map;
}

// Every pixel of the render shows the same lookup, made with the direction
// uniform `dir`.
inline const char* const kLookupFragment = R"(#version 140
uniform samplerCube Env;
uniform vec3 dir;
out vec4 FragColor;
void main() { FragColor = texture(Env, dir); }
)";

inline const char* const kPositionVertex = R"(#version 140
in vec3 position;
void main() { gl_Position = vec4(position, 1.0); }
)";

inline RenderJob lookupJob(const CubeMap& map, std::array<float, 3> direction) {
  Triangles quad;
  quad.fullScreen(0.5f, {0, 0, 0, 0});
  RenderJob job;
  job.program = program(kPositionVertex, kLookupFragment);
  job.attributes["position"] = attribute("position", 3, quad.positions);
  job.indices = quad.indices;
  job.uniforms["dir"] = value(ValueType::Vec3, {direction[0], direction[1], direction[2]});
  job.cubeMaps["Env"] = &map;
  job.width = 4;
  job.height = 4;
  return job;
}

}  // namespace snell::gltest
