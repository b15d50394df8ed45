#pragma once

#include <opencv2/core.hpp>

#include <vector>

#include "explorer/navigation_grid.h"

namespace stereonav {

// A connected run of frontier cells: known-free cells next to unknown ones, where looking further
// adds to the map.
struct Frontier {
  std::vector<cv::Point> cells;  // (col, row)
  double centroid_x = 0.0;       // world metres (the grid's frame)
  double centroid_y = 0.0;
  // The area of the largest unresolved region the frontier borders: a pocket enclosed by known
  // space (under a desk, behind a cabinet) is small; the unexplored rest of the building, joined
  // up through the unknown around the map, is large.
  double unseen_area_m2 = 0.0;
  // Some cell of it borders unknown space, not only obstacles seen from far: looking there shows
  // new floor, not only where a known wall is.
  bool borders_unknown = false;
};

// Frontier cells are free cells with an unknown or imprecise 4-neighbour (imprecise: an obstacle
// seen only from far, which a closer look resolves) that is not a gap in a surface already pinned
// down (touching a precise obstacle, or with one two cells behind); they are grouped by 8-connectivity
// and groups of fewer than `min_cells` cells are dropped (a lone unknown cell amid free space is
// a gap in the stereo data, not an opening). Largest first.
std::vector<Frontier> findFrontiers(const NavigationGrid& grid, int min_cells);

}  // namespace stereonav
