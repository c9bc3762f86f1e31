#pragma once
// Where each point's label goes on a chart, so that no two labels print on
// top of each other: methods often sit close together (two that draw the
// same picture at the same cost coincide). Positions are in character cells
// of the plot area, the unit of gnuplot's `offset character`.
#include <string>
#include <vector>

namespace snell::bench {

struct LabelledPoint {
  double x = 0, y = 0;  // the point, in character cells from the plot's lower left
  std::string text;
};

// A label's lower-left-anchored box: left-justified text whose baseline
// middle sits at (x + dx, y + dy).
struct LabelOffset {
  double dx = 0, dy = 0;
};

struct LabelBox {
  double left = 0, right = 0, bottom = 0, top = 0;
};

// The box a label's text covers, at `scale` times the width of a character
// of the offsets' font (labels are drawn in a smaller font).
LabelBox labelBox(const LabelledPoint& p, const LabelOffset& o, double scale);
bool overlaps(const LabelBox& a, const LabelBox& b);

// One offset per point, in the points' order. Each label takes the first
// place, nearest its point first (right and above, right and below, then
// further up and down, then the left side), that overlaps no label placed
// before it and no other point's marker; points are placed left to right,
// bottom to top, so the result does not depend on the input order's ties.
// When every place is taken the label goes where it overlaps least.
std::vector<LabelOffset> placeLabels(const std::vector<LabelledPoint>& points, double scale);

}  // namespace snell::bench
