#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace stereonav {

// Cells [col_begin, col_end) of grid row `row`: the rasteriser's output, so that filling a
// region costs one small record per row and never one allocation per cell.
struct CellSpan {
  int row;
  int col_begin;
  int col_end;
};

// Spans of one scan. Storage only grows (so after the first scan rasterising allocates nothing)
// and room is handed out before it is filled, so the rasteriser writes each span once.
class CellSpanBuffer {
 public:
  size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  const CellSpan* begin() const { return storage_.data(); }
  const CellSpan* end() const { return storage_.data() + size_; }
  const CellSpan& operator[](size_t i) const { return storage_[i]; }
  void clear() { size_ = 0; }

  // Room for `count` more spans after the current ones; commit() says how many were written.
  CellSpan* room(size_t count) {
    if (storage_.size() < size_ + count) storage_.resize(2 * (size_ + count));
    return storage_.data() + size_;
  }
  void commit(const CellSpan* written_end) {
    size_ = static_cast<size_t>(written_end - storage_.data());
  }

 private:
  std::vector<CellSpan> storage_;
  size_t size_ = 0;
};

// The cells a rasteriser may emit: columns [col_begin, col_end) and rows [row_begin, row_end),
// e.g. a grid's cells, so that its consumers need no bounds checks. Clipping costs nothing per
// row: it narrows the polygon's column range and its row range up front.
struct CellWindow {
  int col_begin;
  int col_end;
  int row_begin;
  int row_end;

  static constexpr int kIndexRange = 1 << 20;  // 2^20 cells of 5 cm are 52 km
  static constexpr CellWindow all() { return {-kIndexRange, kIndexRange, -kIndexRange, kIndexRange}; }
  static constexpr CellWindow grid(int width, int height) { return {0, width, 0, height}; }
};

// A point in continuous cell units: cell (i, j) covers [i, i+1) x [j, j+1), its centre is
// (i + 0.5, j + 0.5).
struct CellPoint {
  double u;
  double v;
};

// The supporting line of a polygon edge as u(v) = u0 + (v - v0) * du_dv. Polygons that share an
// edge must be given the SAME EdgeLine (same numbers): then both evaluate it to bit-identical u
// at every row and the half-open rule below hands each cell centre on it to exactly one of them.
struct EdgeLine {
  double u0;
  double v0;
  double du_dv;

  double uAt(double v) const { return u0 + (v - v0) * du_dv; }
  // The line through a and b; a horizontal edge (a.v == b.v) only bounds rows, never columns.
  static EdgeLine through(const CellPoint& a, const CellPoint& b) {
    return {a.u, a.v, (b.u - a.u) / (b.v - a.v)};
  }
};

// A convex polygon of 3 or 4 vertices in counter-clockwise order; edges[i] runs from vertex i
// to vertex (i + 1) % size.
struct ConvexPolygon {
  std::array<CellPoint, 4> vertices;
  std::array<EdgeLine, 4> edges;
  int size = 0;
};

// An edge of a general polygon for appendPolygonSpans: its supporting line and which way it
// runs (counter-clockwise polygons: +1 going down, i.e. entering when scanning towards +u).
struct ScanEdge {
  EdgeLine line;
  double v_low;
  double v_high;
  double u_low;  // the edge's u-range bounds its crossings (nearly horizontal edges overshoot)
  double u_high;
  int winding;

  // The edge from a to b on `line` (which must pass through both); horizontal edges are dropped.
  static void appendTo(std::vector<ScanEdge>& edges, const CellPoint& a, const CellPoint& b,
                       const EdgeLine& line) {
    if (a.v == b.v) return;
    edges.push_back({line, std::min(a.v, b.v), std::max(a.v, b.v), std::min(a.u, b.u),
                     std::max(a.u, b.u), b.v < a.v ? 1 : -1});
  }
};

// Exact scan conversion: appends one span per row for the cells whose centre lies inside the
// polygon. "Inside" is half-open so that polygons tiling the plane never share a cell: a centre
// exactly on an edge belongs to the polygon on the edge's right (larger u), or above it (larger
// v) for a horizontal edge. Rows and columns are unbounded (negative indices are possible); the
// caller sizes the grid first, or passes its window.
void appendCellSpans(const ConvexPolygon& polygon, CellSpanBuffer& spans,
                     const CellWindow& window = CellWindow::all());

// Storage for appendPolygonSpans, kept by a caller that fills a polygon per scan so that after
// the first one it allocates nothing.
struct PolygonScanScratch {
  struct Crossing {
    double u;
    int winding;
  };
  std::vector<int> row_offsets;  // per row, where its crossings start in `crossings`
  std::vector<Crossing> crossings;
};

// The same for any polygon, or set of polygons that do not overlap, given as counter-clockwise
// edges (nonzero winding): per row, the edges crossing the row's centre line are sorted and the
// cells between entering and leaving crossings are taken with the same half-open rule, so that
// shared EdgeLines split cells with convex neighbours exactly. Cost per row grows with the edges
// crossing it, not with the polygon's size.
void appendPolygonSpans(const std::vector<ScanEdge>& edges, CellSpanBuffer& spans,
                        const CellWindow& window = CellWindow::all(),
                        PolygonScanScratch* scratch = nullptr);

}  // namespace stereonav
