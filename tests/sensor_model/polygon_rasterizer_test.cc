#include "sensor_model/polygon_rasterizer.h"

#include <gtest/gtest.h>

#include <set>
#include <utility>
#include <vector>

namespace stereonav {
namespace {

using Cells = std::set<std::pair<int, int>>;  // (col, row)

ConvexPolygon polygonFrom(const std::vector<CellPoint>& ccw) {
  ConvexPolygon polygon;
  polygon.size = static_cast<int>(ccw.size());
  for (int i = 0; i < polygon.size; ++i) {
    polygon.vertices[i] = ccw[i];
    polygon.edges[i] = EdgeLine::through(ccw[i], ccw[(i + 1) % polygon.size]);
  }
  return polygon;
}

Cells cellsOf(const CellSpanBuffer& spans) {
  Cells cells;
  for (const CellSpan& span : spans) {
    for (int col = span.col_begin; col < span.col_end; ++col) cells.insert({col, span.row});
  }
  return cells;
}

TEST(PolygonRasterizerTest, AxisAlignedSquareTakesCentresOnLeftAndBottomEdgesOnly) {
  // Square [1, 3] x [1, 3] in cell units: centres (1.5, 1.5), (2.5, 1.5), (1.5, 2.5), (2.5, 2.5)
  // are strictly inside; no centre lies on its edges.
  CellSpanBuffer spans;
  appendCellSpans(polygonFrom({{1, 1}, {3, 1}, {3, 3}, {1, 3}}), spans);
  EXPECT_EQ(cellsOf(spans), (Cells{{1, 1}, {2, 1}, {1, 2}, {2, 2}}));
  // Square [0.5, 2.5] x [0.5, 2.5]: centres 0.5, 1.5 on the left/bottom edges are in, centres at
  // 2.5 on the right/top edges are out.
  spans.clear();
  appendCellSpans(polygonFrom({{0.5, 0.5}, {2.5, 0.5}, {2.5, 2.5}, {0.5, 2.5}}), spans);
  EXPECT_EQ(cellsOf(spans), (Cells{{0, 0}, {1, 0}, {0, 1}, {1, 1}}));
  ASSERT_EQ(spans.size(), 2u);  // one span per row
  EXPECT_EQ(spans[0].row, 0);
  EXPECT_EQ(spans[0].col_begin, 0);
  EXPECT_EQ(spans[0].col_end, 2);
}

TEST(PolygonRasterizerTest, TriangleWithCentresOnSlopedEdges) {
  // Right triangle (0.5,0.5) (4.5,0.5) (0.5,4.5): the hypotenuse u + v = 5 passes through the
  // centres (4.5,0.5)... (0.5,4.5) i.e. cells with col + row = 4. The polygon lies left of it
  // (smaller u), so those are out; the bottom row and left column are in.
  CellSpanBuffer spans;
  appendCellSpans(polygonFrom({{0.5, 0.5}, {4.5, 0.5}, {0.5, 4.5}}), spans);
  Cells expected;
  for (int row = 0; row < 4; ++row) {
    for (int col = 0; col + row < 4; ++col) expected.insert({col, row});
  }
  EXPECT_EQ(cellsOf(spans), expected);
}

TEST(PolygonRasterizerTest, NeighboursSharingAnEdgeSplitItsCentresWithoutOverlap) {
  // Two triangles sharing the diagonal from (0.5,0.5) to (4.5,4.5), which passes through the
  // centres of cells (k, k): each of those goes to the triangle on its right (larger u).
  const CellPoint a{0.5, 0.5}, b{4.5, 0.5}, c{4.5, 4.5}, d{0.5, 4.5};
  const EdgeLine diagonal = EdgeLine::through(a, c);
  ConvexPolygon lower = polygonFrom({a, b, c});
  lower.edges[2] = diagonal;  // c -> a, the same line as the neighbour's a -> c
  ConvexPolygon upper = polygonFrom({a, c, d});
  upper.edges[0] = diagonal;
  CellSpanBuffer lower_spans, upper_spans;
  appendCellSpans(lower, lower_spans);
  appendCellSpans(upper, upper_spans);
  const Cells lower_cells = cellsOf(lower_spans);
  const Cells upper_cells = cellsOf(upper_spans);
  for (int k = 0; k < 4; ++k) {
    EXPECT_TRUE(lower_cells.count({k, k})) << k;
    EXPECT_FALSE(upper_cells.count({k, k})) << k;
  }
  for (const auto& cell : lower_cells) EXPECT_FALSE(upper_cells.count(cell));
  // Together they cover the square [0.5, 4.5)^2 exactly: 4 x 4 centres.
  EXPECT_EQ(lower_cells.size() + upper_cells.size(), 16u);
}

TEST(PolygonRasterizerTest, NegativeCellIndicesAndDegeneratePolygons) {
  CellSpanBuffer spans;
  appendCellSpans(polygonFrom({{-3, -2}, {-1, -2}, {-1, -1}, {-3, -1}}), spans);
  EXPECT_EQ(cellsOf(spans), (Cells{{-3, -2}, {-2, -2}}));
  spans.clear();
  appendCellSpans(polygonFrom({{0, 0}, {5, 0}, {9, 0}}), spans);  // a segment
  EXPECT_TRUE(spans.empty());
}

TEST(PolygonRasterizerTest, NonConvexPolygonMatchesItsConvexPieces) {
  // An L shape (counter-clockwise) = the squares [0.5,2.5)x[0.5,1.5) and [0.5,1.5)x[1.5,3.5),
  // with centres on its edges: same cells as the two convex pieces, bottom/left edges in.
  const std::vector<CellPoint> l_shape{{0.5, 0.5}, {2.5, 0.5}, {2.5, 1.5},
                                       {1.5, 1.5}, {1.5, 3.5}, {0.5, 3.5}};
  std::vector<ScanEdge> edges;
  for (size_t i = 0; i < l_shape.size(); ++i) {
    const CellPoint& a = l_shape[i];
    const CellPoint& b = l_shape[(i + 1) % l_shape.size()];
    ScanEdge::appendTo(edges, a, b, EdgeLine::through(a, b));
  }
  CellSpanBuffer spans;
  appendPolygonSpans(edges, spans);
  EXPECT_EQ(cellsOf(spans), (Cells{{0, 0}, {1, 0}, {0, 1}, {0, 2}}));
}

TEST(PolygonRasterizerTest, FanOfTrianglesFilledAsOnePolygonEqualsTheTriangles) {
  // Three triangles around (5.2, 4.9) with a shared apex, filled one by one and as their union.
  const CellPoint apex{5.2, 4.9};
  const std::vector<CellPoint> rim{{9.7, 1.1}, {10.3, 6.6}, {6.1, 9.8}, {1.2, 8.3}};
  CellSpanBuffer separate;
  std::vector<ScanEdge> edges;
  for (size_t i = 0; i + 1 < rim.size(); ++i) {
    appendCellSpans(polygonFrom({apex, rim[i], rim[i + 1]}), separate);
    ScanEdge::appendTo(edges, rim[i], rim[i + 1], EdgeLine::through(rim[i], rim[i + 1]));
  }
  ScanEdge::appendTo(edges, apex, rim.front(), EdgeLine::through(apex, rim.front()));
  ScanEdge::appendTo(edges, rim.back(), apex, EdgeLine::through(rim.back(), apex));
  CellSpanBuffer together;
  appendPolygonSpans(edges, together);
  EXPECT_EQ(cellsOf(together), cellsOf(separate));
  EXPECT_GT(cellsOf(together).size(), 20u);
}

}  // namespace
}  // namespace stereonav
