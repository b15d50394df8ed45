#pragma once

#include <array>
#include <vector>

namespace stereonav {

// Cells [col_begin, col_end) of grid row `row`: the rasteriser's output, so that filling a
// region costs one small record per row and never one allocation per cell.
struct CellSpan {
  int row;
  int col_begin;
  int col_end;
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

// Exact scan conversion: appends one span per row for the cells whose centre lies inside the
// polygon. "Inside" is half-open so that polygons tiling the plane never share a cell: a centre
// exactly on an edge belongs to the polygon on the edge's right (larger u), or above it (larger
// v) for a horizontal edge. Rows and columns are unbounded (negative indices are possible); the
// caller sizes the grid first.
void appendCellSpans(const ConvexPolygon& polygon, std::vector<CellSpan>& spans);

}  // namespace stereonav
