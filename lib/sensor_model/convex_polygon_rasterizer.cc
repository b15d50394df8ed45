#include "sensor_model/convex_polygon_rasterizer.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace stereonav {

void appendCellSpans(const ConvexPolygon& polygon, std::vector<CellSpan>& spans) {
  // A convex polygon is the intersection of its edges' half-planes. Walking counter-clockwise
  // the interior is on the left, so an edge going up (+v) bounds the columns from above
  // (u <= line) and one going down bounds them from below (u >= line); horizontal edges only
  // limit the rows, which the vertices' v-range already does.
  std::array<const EdgeLine*, 4> lower{};
  std::array<const EdgeLine*, 4> upper{};
  int lower_count = 0;
  int upper_count = 0;
  double v_min = std::numeric_limits<double>::infinity();
  double v_max = -std::numeric_limits<double>::infinity();
  double u_min = std::numeric_limits<double>::infinity();
  double u_max = -std::numeric_limits<double>::infinity();
  for (int i = 0; i < polygon.size; ++i) {
    const CellPoint& from = polygon.vertices[i];
    const CellPoint& to = polygon.vertices[(i + 1) % polygon.size];
    v_min = std::min(v_min, from.v);
    v_max = std::max(v_max, from.v);
    u_min = std::min(u_min, from.u);
    u_max = std::max(u_max, from.u);
    if (to.v > from.v) {
      upper[upper_count++] = &polygon.edges[i];
    } else if (to.v < from.v) {
      lower[lower_count++] = &polygon.edges[i];
    }
  }
  if (lower_count == 0 || upper_count == 0) return;  // degenerate (a segment or a point)

  // Row j is in when its centre j + 0.5 is in [v_min, v_max); column i when i + 0.5 is in
  // [u_low, u_high). Nearly horizontal edges evaluate far outside the polygon, so the interval is
  // also kept within the vertices' u-range.
  const int row_begin = static_cast<int>(std::ceil(v_min - 0.5));
  const int row_end = static_cast<int>(std::ceil(v_max - 0.5));
  for (int row = row_begin; row < row_end; ++row) {
    const double v = row + 0.5;
    double u_low = u_min;
    for (int k = 0; k < lower_count; ++k) u_low = std::max(u_low, lower[k]->uAt(v));
    double u_high = u_max;
    for (int k = 0; k < upper_count; ++k) u_high = std::min(u_high, upper[k]->uAt(v));
    const int col_begin = static_cast<int>(std::ceil(u_low - 0.5));
    const int col_end = static_cast<int>(std::ceil(u_high - 0.5));
    if (col_end > col_begin) spans.push_back({row, col_begin, col_end});
  }
}

}  // namespace stereonav
