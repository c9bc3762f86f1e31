#include "oracle/reference/cube_sampling.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace snell {
namespace {

// A signed coordinate axis: sign * e_axis.
struct SignedAxis {
  int axis;
  double sign;
};

// Each face's major axis and the axes that sc and tc read (OpenGL 4.6
// table 8.19; the Vulkan table is the same): on +X, sc = -rz and tc = -ry.
struct FaceFrame {
  SignedAxis major, s, t;
};
constexpr std::array<FaceFrame, 6> kFaceFrames = {{
    {{0, +1.0}, {2, -1.0}, {1, -1.0}},  // +X: sc = -rz, tc = -ry
    {{0, -1.0}, {2, +1.0}, {1, -1.0}},  // -X: sc = +rz, tc = -ry
    {{1, +1.0}, {0, +1.0}, {2, +1.0}},  // +Y: sc = +rx, tc = +rz
    {{1, -1.0}, {0, +1.0}, {2, -1.0}},  // -Y: sc = +rx, tc = -rz
    {{2, +1.0}, {0, +1.0}, {1, -1.0}},  // +Z: sc = +rx, tc = -ry
    {{2, -1.0}, {0, -1.0}, {1, -1.0}},  // -Z: sc = -rx, tc = -ry
}};

int clampIndex(int index, int size) { return std::clamp(index, 0, size - 1); }

bool insideFace(int index, int size) { return index >= 0 && index < size; }

struct Texel {
  int face, i, j;
};

// A texel one step beyond exactly one edge of `face`, found on the adjacent
// face as the seamless rules say ("the adjacent texel from the appropriate
// neighboring face"): the texel's centre, on the face's plane of the unit
// cube, is folded over the cube's edge onto the neighbouring face, keeping
// its distance from the edge and its position along it.
Texel acrossEdge(const Texel& texel, int size) {
  const FaceFrame& frame = kFaceFrames[texel.face];
  const double sc = (2.0 * texel.i + 1.0) / size - 1.0;
  const double tc = (2.0 * texel.j + 1.0) / size - 1.0;
  Direction point{};
  point[frame.major.axis] = frame.major.sign;
  point[frame.s.axis] = frame.s.sign * sc;
  point[frame.t.axis] = frame.t.sign * tc;
  const int beyond = insideFace(texel.i, size) ? frame.t.axis : frame.s.axis;
  const double overshoot = std::fabs(point[beyond]) - 1.0;
  point[beyond] = std::copysign(1.0, point[beyond]);
  point[frame.major.axis] = frame.major.sign * (1.0 - overshoot);
  const FaceCoordinates folded = selectCubeFace(point);
  return {folded.face, clampIndex(static_cast<int>(std::floor(folded.s * size)), size),
          clampIndex(static_cast<int>(std::floor(folded.t * size)), size)};
}

Rgba fetch(const CubeMap& map, const Texel& texel) {
  const float* p =
      &map.faces[texel.face][(static_cast<std::size_t>(texel.j) * map.size + texel.i) * 4];
  return {p[0], p[1], p[2], p[3]};
}

Rgba sampleNearest(const CubeMap& map, const FaceCoordinates& at) {
  const int i = clampIndex(static_cast<int>(std::floor(at.s * map.size)), map.size);
  const int j = clampIndex(static_cast<int>(std::floor(at.t * map.size)), map.size);
  return fetch(map, {at.face, i, j});
}

Rgba sampleLinear(const CubeMap& map, const FaceCoordinates& at) {
  const int size = map.size;
  const double u = at.s * size - 0.5;
  const double v = at.t * size - 0.5;
  const int i0 = static_cast<int>(std::floor(u));
  const int j0 = static_cast<int>(std::floor(v));
  const double alpha = u - i0;
  const double beta = v - j0;
  // The footprint in the Vulkan weight order: (i0,j0) (i1,j0) (i0,j1) (i1,j1).
  const std::array<Texel, 4> footprint = {
      {{at.face, i0, j0}, {at.face, i0 + 1, j0}, {at.face, i0, j0 + 1}, {at.face, i0 + 1, j0 + 1}}};
  const std::array<double, 4> weights = {(1 - alpha) * (1 - beta), alpha * (1 - beta),
                                         (1 - alpha) * beta, alpha * beta};
  std::array<Rgba, 4> values{};
  int corner = -1;
  for (int k = 0; k < 4; ++k) {
    const Texel& texel = footprint[k];
    const bool iInside = insideFace(texel.i, size);
    const bool jInside = insideFace(texel.j, size);
    if (!map.seamless) {
      values[k] = fetch(map, {texel.face, clampIndex(texel.i, size), clampIndex(texel.j, size)});
    } else if (iInside && jInside) {
      values[k] = fetch(map, texel);
    } else if (iInside || jInside) {
      values[k] = fetch(map, acrossEdge(texel, size));
    } else {
      corner = k;  // filled in once the other three are known
    }
  }
  // Beyond both edges there is no neighbouring face; the texel is replaced
  // by the average of the three texels that meet at the cube's corner, which
  // are the footprint's other three (Vulkan "Cube Map Corner Texel").
  if (corner >= 0) {
    for (int c = 0; c < 4; ++c) {
      double sum = 0;
      for (int k = 0; k < 4; ++k)
        if (k != corner) sum += values[k][c];
      values[corner][c] = sum / 3.0;
    }
  }
  Rgba result{};
  for (int c = 0; c < 4; ++c)
    for (int k = 0; k < 4; ++k) result[c] += weights[k] * values[k][c];
  return result;
}

}  // namespace

FaceCoordinates selectCubeFace(const Direction& r) {
  const double ax = std::fabs(r[0]), ay = std::fabs(r[1]), az = std::fabs(r[2]);
  int axis = 0;
  if (az >= ax && az >= ay) {
    axis = 2;
  } else if (ay >= ax) {
    axis = 1;
  }
  const int face = 2 * axis + (r[axis] < 0 ? 1 : 0);
  const FaceFrame& frame = kFaceFrames[face];
  const double ma = std::fabs(r[axis]);
  const double sc = frame.s.sign * r[frame.s.axis];
  const double tc = frame.t.sign * r[frame.t.axis];
  return {face, 0.5 * (sc / ma + 1.0), 0.5 * (tc / ma + 1.0)};
}

Rgba sampleCube(const CubeMap& map, const Direction& direction) {
  const FaceCoordinates at = selectCubeFace(direction);
  return map.filter == CubeFilter::Nearest ? sampleNearest(map, at) : sampleLinear(map, at);
}

bool nearCubeFaceEdge(const Direction& direction) {
  std::array<double, 3> magnitude = {std::fabs(direction[0]), std::fabs(direction[1]),
                                     std::fabs(direction[2])};
  std::sort(magnitude.begin(), magnitude.end());
  const double ma = magnitude[2];
  if (ma == 0.0) return false;
  return ma - magnitude[1] <= kFaceEdgeRelativeEpsilon * ma;
}

}  // namespace snell
