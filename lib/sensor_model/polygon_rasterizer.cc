#include "sensor_model/polygon_rasterizer.h"

#include <algorithm>

namespace stereonav {

namespace {

constexpr double kIndexRange = CellWindow::kIndexRange;

// The first cell whose centre (index + 0.5) is at or beyond u, for |u| < kIndexRange (windows
// keep it there; farther values and NaN are clamped to it, so no far vertex can overflow the conversion):
// ceil(u - 0.5), computed as
// kIndexRange - trunc(kIndexRange + 0.5 - u) since truncating a positive value floors it. One
// conversion, where std::ceil is a library call without SSE4.1 and truncate-and-compare converts
// back to double, which makes each row wait for the previous one. The offset rounds u to 2^-32
// cells, far below the rounding in u itself; exact when u - 0.5 is a whole number.
inline int firstCellFrom(double u) {
  u = u > -kIndexRange ? std::min(u, kIndexRange) : -kIndexRange;  // NaN too
  return static_cast<int>(kIndexRange) - static_cast<int>(kIndexRange + 0.5 - u);
}

// The crossings are bucketed by row, edge by edge, rather than found row by row from a list of
// active edges kept sorted by v_low: no sort of the edges, and each edge's crossings come from
// one tight loop. First each row's count (+1 where an edge starts, -1 where it ends, summed),
// then where each row's crossings start. Afterwards row r's crossings are
// [offsets[r - 1], offsets[r]) (row_begin's from 0).
void bucketCrossingsByRow(const std::vector<ScanEdge>& edges, int row_begin, int row_end,
                          PolygonScanScratch& storage) {
  std::vector<int>& offsets = storage.row_offsets;
  offsets.assign(static_cast<size_t>(row_end - row_begin) + 1, 0);
  for (const ScanEdge& edge : edges) {
    const int first = std::max(firstCellFrom(edge.v_low), row_begin);
    const int end = std::min(firstCellFrom(edge.v_high), row_end);
    if (first >= end) continue;
    ++offsets[first - row_begin];
    --offsets[end - row_begin];
  }
  int active = 0, total = 0;
  for (int& offset : offsets) {
    active += offset;
    offset = total;
    total += active;
  }
  std::vector<PolygonScanScratch::Crossing>& crossings = storage.crossings;
  if (crossings.size() < static_cast<size_t>(total)) crossings.resize(2 * total);
  // offsets[r] counts up as row r's crossings are filled in, ending where row r + 1 starts.
  for (const ScanEdge& edge : edges) {
    const int first = std::max(firstCellFrom(edge.v_low), row_begin);
    const int end = std::min(firstCellFrom(edge.v_high), row_end);
    double v = first + 0.5;  // stays exact
    for (int row = first; row < end; ++row, v += 1.0) {
      crossings[offsets[row - row_begin]++] = {
          std::clamp(edge.line.uAt(v), edge.u_low, edge.u_high), edge.winding};
    }
  }
}

// One row's spans from its crossings: inside where the winding number is positive.
void appendRowSpans(PolygonScanScratch::Crossing* first, PolygonScanScratch::Crossing* last, int row,
                    const CellWindow& window, CellSpanBuffer& spans) {
  // Usually two crossings; a frontier running along the row (a wall seen at a grazing angle)
  // can bring a hundred.
  if (last - first == 2) {
    if (first[1].u < first[0].u) std::swap(first[0], first[1]);
  } else {
    std::sort(first, last, [](const PolygonScanScratch::Crossing& a,
                              const PolygonScanScratch::Crossing& b) { return a.u < b.u; });
  }
  int winding = 0;
  double entered = 0.0;
  for (const PolygonScanScratch::Crossing* crossing = first; crossing != last; ++crossing) {
    const int before = winding;
    winding += crossing->winding;
    if (before <= 0 && winding > 0) entered = crossing->u;
    if (before > 0 && winding <= 0) {
      const int col_begin = std::max(firstCellFrom(entered), window.col_begin);
      const int col_end = std::min(firstCellFrom(crossing->u), window.col_end);
      if (col_end > col_begin) {
        CellSpan* out = spans.room(1);
        *out = {row, col_begin, col_end};
        spans.commit(out + 1);
      }
    }
  }
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

void appendPolygonSpans(const std::vector<ScanEdge>& edges, CellSpanBuffer& spans,
                        const CellWindow& window, PolygonScanScratch* scratch) {
  PolygonScanScratch local_scratch;
  PolygonScanScratch& storage = scratch != nullptr ? *scratch : local_scratch;
  // An edge crosses the centre lines v = row + 0.5 with v_low <= v < v_high: rows
  // [firstCellFrom(v_low), firstCellFrom(v_high)).
  int row_begin = window.row_end, row_end = window.row_begin;
  for (const ScanEdge& edge : edges) {
    row_begin = std::min(row_begin, firstCellFrom(edge.v_low));
    row_end = std::max(row_end, firstCellFrom(edge.v_high));
  }
  row_begin = std::max(row_begin, window.row_begin);
  row_end = std::min(row_end, window.row_end);
  if (row_end <= row_begin) return;

  bucketCrossingsByRow(edges, row_begin, row_end, storage);
  int row_first = 0;
  for (int row = row_begin; row < row_end; ++row) {
    const int row_last = storage.row_offsets[row - row_begin];
    appendRowSpans(storage.crossings.data() + row_first, storage.crossings.data() + row_last, row,
                   window, spans);
    row_first = row_last;
  }
}

}  // namespace stereonav
