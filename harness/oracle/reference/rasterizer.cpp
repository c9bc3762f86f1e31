#include "oracle/reference/rasterizer.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/errors.h"

namespace snell {
namespace {

// Coverage is decided on window coordinates snapped to 1/256 pixel, as
// llvmpipe and lavapipe do (8 sub-pixel bits), with exact integer edge
// functions: a pixel centre on an edge shared by two triangles is then
// covered by exactly one of them, which double arithmetic on unsnapped
// coordinates cannot promise.
constexpr int kSubpixelBits = 8;
constexpr double kSubpixelScale = 1 << kSubpixelBits;
// Keeps the edge-function products below 2^62.
constexpr double kLargestWindowCoordinate = 1 << 21;

struct WindowVertex {
  double x, y;   // image coordinates: x right, y down, pixel centres at +0.5
  double depth;  // window z, depth range [0, 1]
  double inverseW;
  std::int64_t fx, fy;  // x, y in sub-pixel units
};

// Twice the signed area of (a, b, p); positive when p is on the interior
// side of a -> b for a triangle whose edgeFunction(v0, v1, v2) is positive.
template <class T>
T edgeFunction(T ax, T ay, T bx, T by, T px, T py) {
  return (bx - ax) * (py - ay) - (by - ay) * (px - ax);
}

// Top-left rule in image coordinates (y down) for the positive orientation:
// a pixel centre exactly on an edge belongs to the triangle when the edge is
// a left edge (going up) or a top edge (horizontal, going right).
bool ownsEdge(const WindowVertex& a, const WindowVertex& b) {
  const std::int64_t dy = b.fy - a.fy;
  return dy < 0 || (dy == 0 && b.fx > a.fx);
}

bool inside(std::int64_t edge, bool owned) { return edge > 0 || (edge == 0 && owned); }

WindowVertex toWindow(const ClipPosition& p, const RasterSettings& settings, std::size_t index) {
  // Viewport (0, 0, width, height): x_w = (x_ndc + 1) * width / 2, y_w
  // likewise (y up from the bottom row); glDepthRange(0, 1).
  const double xNdc = p.x / p.w, yNdc = p.y / p.w, zNdc = p.z / p.w;
  const double xWindow = (xNdc + 1.0) * 0.5 * settings.width;
  const double yWindow = (yNdc + 1.0) * 0.5 * settings.height;
  const double yImage = settings.height - yWindow;
  if (!(std::fabs(xWindow) <= kLargestWindowCoordinate &&
        std::fabs(yImage) <= kLargestWindowCoordinate)) {
    throw UsageError(fmt::format(
        "reference image: vertex {} projects {:.3g} pixels away (w = {:.3g}): the reference "
        "renders geometry well in front of the camera only",
        index, std::max(std::fabs(xWindow), std::fabs(yImage)), p.w));
  }
  return {xWindow,
          yImage,
          0.5 * zNdc + 0.5,
          1.0 / p.w,
          std::llround(xWindow * kSubpixelScale),
          std::llround(yImage * kSubpixelScale)};
}

bool finite(const ClipPosition& p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && std::isfinite(p.w);
}

// Whether clipping would leave any of the triangle, and whether it can be
// drawn without clipping at w = 0. A triangle with all three vertices
// outside one clip plane is wholly outside the (convex) clip volume. With
// every w > 0, clipping at the near and far planes is the same as
// discarding the fragments whose interpolated depth leaves [0, 1], which
// the depth step does, and the x and y planes are the viewport's edges.
bool drawable(const std::array<ClipPosition, 3>& p, std::size_t triangle) {
  auto all = [&](auto outside) { return std::all_of(p.begin(), p.end(), outside); };
  const bool outside = all([](const ClipPosition& v) { return v.x < -v.w; }) ||
                       all([](const ClipPosition& v) { return v.x > v.w; }) ||
                       all([](const ClipPosition& v) { return v.y < -v.w; }) ||
                       all([](const ClipPosition& v) { return v.y > v.w; }) ||
                       all([](const ClipPosition& v) { return v.z < -v.w; }) ||
                       all([](const ClipPosition& v) { return v.z > v.w; });
  if (outside) return false;
  if (p[0].w > 0 && p[1].w > 0 && p[2].w > 0) return true;
  throw UsageError(fmt::format(
      "reference image: triangle {} crosses the near plane; the reference renders geometry in "
      "front of the camera only",
      triangle));
}

class TriangleRasterizer {
 public:
  TriangleRasterizer(const RasterSettings& settings, Visibility& out, std::vector<double>& depth)
      : settings_(settings), out_(out), depth_(depth) {}

  void draw(std::array<WindowVertex, 3> v, std::uint32_t triangle) {
    std::array<int, 3> order = {0, 1, 2};
    const std::int64_t area = edgeFunction(v[0].fx, v[0].fy, v[1].fx, v[1].fy, v[2].fx, v[2].fy);
    if (area == 0) return;
    // Counter-clockwise in GL window coordinates (y up) is clockwise in image
    // coordinates (y down): a negative area here is a front face.
    const bool front = area < 0;
    if (settings_.cullBackFaces && !front) return;
    if (area < 0) {
      std::swap(v[1], v[2]);
      std::swap(order[1], order[2]);
    }
    const double areaExact = edgeFunction(v[0].x, v[0].y, v[1].x, v[1].y, v[2].x, v[2].y);
    if (areaExact == 0) return;
    const std::array<bool, 3> owned = {ownsEdge(v[1], v[2]), ownsEdge(v[2], v[0]),
                                       ownsEdge(v[0], v[1])};

    const auto [minX, maxX] = std::minmax({v[0].x, v[1].x, v[2].x});
    const auto [minY, maxY] = std::minmax({v[0].y, v[1].y, v[2].y});
    const int x0 = std::max(0, static_cast<int>(std::floor(minX - 0.5)));
    const int x1 = std::min(settings_.width - 1, static_cast<int>(std::ceil(maxX - 0.5)));
    const int y0 = std::max(0, static_cast<int>(std::floor(minY - 0.5)));
    const int y1 = std::min(settings_.height - 1, static_cast<int>(std::ceil(maxY - 0.5)));

    constexpr std::int64_t kHalf = 1 << (kSubpixelBits - 1);
    for (int y = y0; y <= y1; ++y) {
      const std::int64_t py = (static_cast<std::int64_t>(y) << kSubpixelBits) + kHalf;
      for (int x = x0; x <= x1; ++x) {
        const std::int64_t px = (static_cast<std::int64_t>(x) << kSubpixelBits) + kHalf;
        if (!inside(edgeFunction(v[1].fx, v[1].fy, v[2].fx, v[2].fy, px, py), owned[0]) ||
            !inside(edgeFunction(v[2].fx, v[2].fy, v[0].fx, v[0].fy, px, py), owned[1]) ||
            !inside(edgeFunction(v[0].fx, v[0].fy, v[1].fx, v[1].fy, px, py), owned[2]))
          continue;
        shade(v, order, areaExact, x, y, triangle);
      }
    }
  }

 private:
  // Weights and depth come from the unsnapped coordinates: snapping decides
  // coverage only, and the reference interpolates at the true pixel centre.
  void shade(const std::array<WindowVertex, 3>& v, const std::array<int, 3>& order, double area,
             int x, int y, std::uint32_t triangle) {
    const double cx = x + 0.5, cy = y + 0.5;
    const std::array<double, 3> screen = {
        edgeFunction(v[1].x, v[1].y, v[2].x, v[2].y, cx, cy) / area,
        edgeFunction(v[2].x, v[2].y, v[0].x, v[0].y, cx, cy) / area,
        edgeFunction(v[0].x, v[0].y, v[1].x, v[1].y, cx, cy) / area};
    // Window z is interpolated linearly in screen space (OpenGL 4.6 section
    // 14.6.1); fragments outside the depth range are the ones near or far
    // clipping would have removed.
    const double z = screen[0] * v[0].depth + screen[1] * v[1].depth + screen[2] * v[2].depth;
    if (!(z >= 0.0 && z <= 1.0)) return;
    const std::size_t pixel = static_cast<std::size_t>(y) * settings_.width + x;
    if (!(z < depth_[pixel])) return;
    depth_[pixel] = z;
    // Perspective-correct: screen weights divided by w, renormalised.
    std::array<double, 3> perspective{};
    double sum = 0;
    for (int k = 0; k < 3; ++k) {
      perspective[k] = screen[k] * v[k].inverseW;
      sum += perspective[k];
    }
    std::array<double, 3>& weights = out_.weights[pixel];
    for (int k = 0; k < 3; ++k) weights[order[k]] = perspective[k] / sum;
    out_.triangle[pixel] = triangle;
  }

  const RasterSettings& settings_;
  Visibility& out_;
  std::vector<double>& depth_;
};

}  // namespace

Visibility rasterize(std::span<const ClipPosition> positions,
                     std::span<const std::uint32_t> indices, const RasterSettings& settings) {
  if (settings.width <= 0 || settings.height <= 0)
    throw UsageError(
        fmt::format("reference image: size {} x {} is empty", settings.width, settings.height));
  if (indices.size() % 3 != 0)
    throw UsageError(
        fmt::format("reference image: {} indices do not make a triangle list", indices.size()));
  for (std::size_t k = 0; k < positions.size(); ++k)
    if (!finite(positions[k]))
      throw UsageError(fmt::format("reference image: gl_Position of vertex {} is not finite", k));

  Visibility out;
  out.width = settings.width;
  out.height = settings.height;
  const std::size_t pixels = static_cast<std::size_t>(settings.width) * settings.height;
  out.triangle.assign(pixels, Visibility::kNoTriangle);
  out.weights.assign(pixels, {0.0, 0.0, 0.0});
  std::vector<double> depth(pixels, 1.0);
  TriangleRasterizer rasterizer(settings, out, depth);

  for (std::size_t first = 0; first < indices.size(); first += 3) {
    const std::size_t triangle = first / 3;
    std::array<ClipPosition, 3> clip;
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t index = indices[first + k];
      if (index >= positions.size())
        throw UsageError(
            fmt::format("reference image: index {} of triangle {} is past the {} "
                        "vertices",
                        index, triangle, positions.size()));
      clip[k] = positions[index];
    }
    if (!drawable(clip, triangle)) continue;
    std::array<WindowVertex, 3> window;
    for (int k = 0; k < 3; ++k) window[k] = toWindow(clip[k], settings, indices[first + k]);
    rasterizer.draw(window, static_cast<std::uint32_t>(triangle));
  }
  return out;
}

}  // namespace snell
