#include "render_geometry.h"

#include <array>
#include <cmath>

namespace snell::vktest {

namespace {

using Vec3 = std::array<double, 3>;

std::uint32_t addVertex(Mesh& mesh, const Vec3& position, const Vec3& normal) {
  const auto index = static_cast<std::uint32_t>(mesh.positions.vertexCount());
  for (double c : position) mesh.positions.data.push_back(static_cast<float>(c));
  mesh.positions.data.push_back(1.0f);
  for (double c : normal) mesh.normals.data.push_back(static_cast<float>(c));
  return index;
}

Vec3 vertexAt(const Mesh& mesh, std::uint32_t index) {
  const float* p = &mesh.positions.data[4 * index];
  return {p[0], p[1], p[2]};
}

// Keeps the triangle counter-clockwise seen from outside a body centred at the origin.
void addOutwardTriangle(Mesh& mesh, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  const Vec3 pa = vertexAt(mesh, a), pb = vertexAt(mesh, b), pc = vertexAt(mesh, c);
  const Vec3 u = {pb[0] - pa[0], pb[1] - pa[1], pb[2] - pa[2]};
  const Vec3 v = {pc[0] - pa[0], pc[1] - pa[1], pc[2] - pa[2]};
  const Vec3 n = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  const double outward = n[0] * (pa[0] + pb[0] + pc[0]) + n[1] * (pa[1] + pb[1] + pc[1]) +
                         n[2] * (pa[2] + pb[2] + pc[2]);
  if (outward >= 0) {
    mesh.indices.insert(mesh.indices.end(), {a, b, c});
  } else {
    mesh.indices.insert(mesh.indices.end(), {a, c, b});
  }
}

}  // namespace

void addRectangle(Mesh& mesh, float x0, float y0, float x1, float y1, float z) {
  const auto first = static_cast<std::uint32_t>(mesh.positions.vertexCount());
  for (const auto& [x, y] :
       {std::array{x0, y0}, std::array{x1, y0}, std::array{x1, y1}, std::array{x0, y1}}) {
    mesh.positions.data.insert(mesh.positions.data.end(), {x, y, z, 1.0f});
  }
  mesh.indices.insert(mesh.indices.end(),
                      {first, first + 1, first + 2, first, first + 2, first + 3});
}

void addTriangle(Mesh& mesh, const float (&corners)[3][2], float z) {
  const auto first = static_cast<std::uint32_t>(mesh.positions.vertexCount());
  for (const auto& corner : corners) {
    mesh.positions.data.insert(mesh.positions.data.end(), {corner[0], corner[1], z, 1.0f});
  }
  mesh.indices.insert(mesh.indices.end(), {first, first + 1, first + 2});
}

Mesh sphere(float radius, int rings, int segments) {
  Mesh mesh;
  const double pi = std::acos(-1.0);
  const std::uint32_t north = addVertex(mesh, {0, radius, 0}, {0, 1, 0});
  std::vector<std::vector<std::uint32_t>> ring(static_cast<std::size_t>(rings - 1));
  for (int r = 1; r < rings; ++r) {
    const double theta = pi * r / rings;
    for (int s = 0; s < segments; ++s) {
      const double phi = 2 * pi * s / segments;
      const Vec3 n = {std::sin(theta) * std::cos(phi), std::cos(theta),
                      std::sin(theta) * std::sin(phi)};
      ring[static_cast<std::size_t>(r - 1)].push_back(
          addVertex(mesh, {radius * n[0], radius * n[1], radius * n[2]}, n));
    }
  }
  const std::uint32_t south = addVertex(mesh, {0, -radius, 0}, {0, -1, 0});
  for (int s = 0; s < segments; ++s) {
    const auto t = static_cast<std::size_t>(s), next = static_cast<std::size_t>((s + 1) % segments);
    addOutwardTriangle(mesh, north, ring.front()[t], ring.front()[next]);
    addOutwardTriangle(mesh, south, ring.back()[next], ring.back()[t]);
    for (std::size_t r = 0; r + 1 < ring.size(); ++r) {
      addOutwardTriangle(mesh, ring[r][t], ring[r + 1][t], ring[r + 1][next]);
      addOutwardTriangle(mesh, ring[r][t], ring[r + 1][next], ring[r][next]);
    }
  }
  return mesh;
}

}  // namespace snell::vktest
