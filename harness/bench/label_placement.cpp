#include "bench/label_placement.h"

#include <algorithm>
#include <numeric>

namespace snell::bench {
namespace {

// A marker's half size in character cells (gnuplot's `ps 1.4` circles).
constexpr double kMarker = 0.45;

double overlapArea(const LabelBox& a, const LabelBox& b) {
  const double w = std::min(a.right, b.right) - std::max(a.left, b.left);
  const double h = std::min(a.top, b.top) - std::max(a.bottom, b.bottom);
  return w > 0 && h > 0 ? w * h : 0.0;
}

std::vector<LabelOffset> candidates(const LabelledPoint& p, double scale) {
  const double width = labelBox(p, {}, scale).right - p.x;
  std::vector<LabelOffset> out;
  // Nearest first: right of the point, alternating above and below, one
  // line further each time; then the same on the left.
  for (double side : {0.8, -0.8 - width})
    for (int step = 0; step < 6; ++step)
      for (double sign : {1.0, -1.0}) out.push_back({side, sign * (0.6 + 1.1 * step)});
  return out;
}

}  // namespace

LabelBox labelBox(const LabelledPoint& p, const LabelOffset& o, double scale) {
  const double width = scale * 0.75 * static_cast<double>(p.text.size());
  const double height = scale * 1.0;
  return {p.x + o.dx, p.x + o.dx + width, p.y + o.dy - height / 2, p.y + o.dy + height / 2};
}

bool overlaps(const LabelBox& a, const LabelBox& b) { return overlapArea(a, b) > 0; }

std::vector<LabelOffset> placeLabels(const std::vector<LabelledPoint>& points, double scale) {
  std::vector<std::size_t> order(points.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if (points[a].x != points[b].x) return points[a].x < points[b].x;
    return points[a].y < points[b].y;
  });
  std::vector<LabelBox> markers;
  for (const LabelledPoint& p : points)
    markers.push_back({p.x - kMarker, p.x + kMarker, p.y - kMarker, p.y + kMarker});

  std::vector<LabelOffset> result(points.size());
  std::vector<LabelBox> placed;
  for (std::size_t i : order) {
    double bestCost = -1;
    LabelOffset best;
    for (const LabelOffset& o : candidates(points[i], scale)) {
      const LabelBox box = labelBox(points[i], o, scale);
      double cost = 0;
      for (const LabelBox& other : placed) cost += overlapArea(box, other);
      for (std::size_t m = 0; m < markers.size(); ++m)
        if (m != i) cost += overlapArea(box, markers[m]);
      if (bestCost < 0 || cost < bestCost) {
        bestCost = cost;
        best = o;
      }
      if (cost == 0) break;
    }
    result[i] = best;
    placed.push_back(labelBox(points[i], best, scale));
  }
  return result;
}

}  // namespace snell::bench
