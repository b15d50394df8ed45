#include "sensor_model/polygon_rasterizer.h"

#include <algorithm>

namespace stereonav {

namespace {

constexpr double kIndexRange = CellWindow::kIndexRange;

// The first cell whose centre (index + 0.5) is at or beyond u, for |u| < kIndexRange (windows
// keep it there): ceil(u - 0.5), computed as
// kIndexRange - trunc(kIndexRange + 0.5 - u) since truncating a positive value floors it. One
// conversion, where std::ceil is a library call without SSE4.1 and truncate-and-compare converts
// back to double, which makes each row wait for the previous one. The offset rounds u to 2^-32
// cells, far below the rounding in u itself; exact when u - 0.5 is a whole number.
inline int firstCellFrom(double u) {
  return static_cast<int>(kIndexRange) - static_cast<int>(kIndexRange + 0.5 - u);
}

}  // namespace

void appendCellSpans(const ConvexPolygon& polygon, CellSpanBuffer& spans,
                     const CellWindow& window) {
  int bottom = 0, top = 0;
  double u_min = polygon.vertices[0].u, u_max = u_min;
  for (int i = 1; i < polygon.size; ++i) {
    const CellPoint& p = polygon.vertices[i];
    if (p.v < polygon.vertices[bottom].v) bottom = i;
    if (p.v > polygon.vertices[top].v) top = i;
    u_min = std::min(u_min, p.u);
    u_max = std::max(u_max, p.u);
  }
  const double v_max = polygon.vertices[top].v;
  if (!(v_max > polygon.vertices[bottom].v)) return;  // degenerate: a horizontal segment or a point
  u_min = std::max(u_min, static_cast<double>(window.col_begin));
  u_max = std::min(u_max, static_cast<double>(window.col_end));

  // Counter-clockwise, the interior is on the left of every edge: walking forwards from the
  // lowest vertex climbs the right side (u <= edge), backwards the left side (u >= edge). Rows
  // are in when their centre j + 0.5 is in [v_min, v_max), cells when i + 0.5 is in
  // [u_low, u_high): so a centre on an edge goes to the polygon right of / above it. Shared
  // edges are evaluated from the same EdgeLine by both polygons, so they agree to the bit.
  // Nearly horizontal edges evaluate far outside the polygon near their ends; the vertices'
  // u-range keeps the interval sane.
  const auto next = [&](int vertex, int step) {
    const int n = vertex + step;  // no modulo: an integer division per step is noticeable here
    return n < 0 ? polygon.size - 1 : (n == polygon.size ? 0 : n);
  };
  int right_from = bottom;
  int right_to = next(bottom, +1), left_to = next(bottom, -1);
  int row = std::max(firstCellFrom(polygon.vertices[bottom].v), window.row_begin);
  const int row_end = std::min(firstCellFrom(v_max), window.row_end);
  // Rows come in stretches between vertex heights, over which both sides keep one edge.
  while (row < row_end) {
    const double v_row = row + 0.5;
    while (right_to != top && polygon.vertices[right_to].v < v_row) {
      right_from = right_to;
      right_to = next(right_to, +1);
    }
    while (left_to != top && polygon.vertices[left_to].v < v_row) left_to = next(left_to, -1);
    // Edge i runs from vertex i to i + 1, so the left side's edge (walked j -> j - 1) is j - 1.
    const EdgeLine& right = polygon.edges[right_from];
    const EdgeLine& left = polygon.edges[left_to];
    const double stretch_top =
        std::min(polygon.vertices[right_to].v, polygon.vertices[left_to].v);
    const int stretch_end = std::min(row_end, std::max(row + 1, firstCellFrom(stretch_top)));
    CellSpan* out = spans.room(static_cast<size_t>(stretch_end - row));
    for (double v = row + 0.5; row < stretch_end; ++row, v += 1.0) {  // v stays exact
      const int col_begin = firstCellFrom(std::max(u_min, left.uAt(v)));
      const int col_end = firstCellFrom(std::min(u_max, right.uAt(v)));
      *out = {row, col_begin, col_end};
      out += col_end > col_begin ? 1 : 0;  // branchless: empty rows are overwritten
    }
    spans.commit(out);
  }
}

void appendPolygonSpans(std::vector<ScanEdge>& edges, CellSpanBuffer& spans,
                        const CellWindow& window) {
  if (edges.empty()) return;
  std::sort(edges.begin(), edges.end(),
            [](const ScanEdge& a, const ScanEdge& b) { return a.v_low < b.v_low; });
  double v_max = edges.front().v_high;
  for (const ScanEdge& edge : edges) v_max = std::max(v_max, edge.v_high);

  struct Crossing {
    double u;
    int winding;
  };
  // Edges crossing the current row: an edge is in for centres v with v_low <= v < v_high.
  std::vector<const ScanEdge*> active;
  std::vector<Crossing> crossings;
  size_t next_edge = 0;
  const int row_end = std::min(firstCellFrom(v_max), window.row_end);
  for (int row = std::max(firstCellFrom(edges.front().v_low), window.row_begin); row < row_end;
       ++row) {
    const double v = row + 0.5;
    while (next_edge < edges.size() && edges[next_edge].v_low <= v) {
      active.push_back(&edges[next_edge++]);
    }
    crossings.clear();
    for (size_t i = 0; i < active.size();) {
      if (active[i]->v_high <= v) {
        active[i] = active.back();
        active.pop_back();
        continue;
      }
      const ScanEdge& edge = *active[i];
      crossings.push_back({std::clamp(edge.line.uAt(v), edge.u_low, edge.u_high), edge.winding});
      ++i;
    }
    // Usually two crossings; a frontier running along the row (a wall seen at a grazing angle)
    // can bring a hundred.
    std::sort(crossings.begin(), crossings.end(),
              [](const Crossing& a, const Crossing& b) { return a.u < b.u; });
    int winding = 0;
    double entered = 0.0;
    for (const Crossing& crossing : crossings) {
      const int before = winding;
      winding += crossing.winding;
      if (before <= 0 && winding > 0) entered = crossing.u;
      if (before > 0 && winding <= 0) {
        const int col_begin = std::max(firstCellFrom(entered), window.col_begin);
        const int col_end = std::min(firstCellFrom(crossing.u), window.col_end);
        if (col_end > col_begin) {
          CellSpan* out = spans.room(1);
          *out = {row, col_begin, col_end};
          spans.commit(out + 1);
        }
      }
    }
  }
}

}  // namespace stereonav
