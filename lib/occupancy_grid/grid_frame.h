#pragma once

namespace stereonav {

// Where a grid's cells are: cell (i, j) covers [origin_x + i r, origin_x + (i+1) r) x
// [origin_y + j r, ...) with r = resolution, x right and y up (MRPT's COccupancyGridMap2D).
// The sensor model rasterises into this frame; the grids and the explorer's lattice share it.
struct GridFrame {
  double origin_x = 0.0;
  double origin_y = 0.0;
  double resolution = 0.05;
};

// Axis-aligned world bounds, e.g. of a scan's regions, used to grow a grid before rasterising.
struct WorldBounds {
  double min_x;
  double max_x;
  double min_y;
  double max_y;
};

}  // namespace stereonav
