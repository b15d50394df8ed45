#pragma once

#include <opencv2/core.hpp>

#include <cmath>
#include <cstdint>
#include <functional>
#include <utility>

#include "occupancy_grid/grid_frame.h"

namespace stereonav {

// Names a grid's cells so that the names survive the grid's growth: a grid grows by whole cells
// (DisparityTaggedGrid::growToInclude), so every cell keeps its place in the lattice anchored at
// the first grid's origin. Rounding a cell centre to a multiple of the resolution would not do:
// with the origin on such a multiple every centre lies half way between two of them.
class WorldCellLattice {
 public:
  using Cell = std::pair<long, long>;
  // For hash sets of cells: the memories look cells up every frame, and trees of a hundred
  // thousand cells cost a cache miss per level.
  struct CellHash {
    size_t operator()(const Cell& cell) const {
      return std::hash<uint64_t>()(static_cast<uint64_t>(cell.first) * 0x9e3779b97f4a7c15ULL ^
                                   static_cast<uint64_t>(cell.second));
    }
  };

  // The first frame anchors the lattice; later ones are assumed whole cells off it.
  void anchor(const GridFrame& frame) {
    if (anchored_) return;
    origin_x_ = frame.origin_x;
    origin_y_ = frame.origin_y;
    resolution_ = frame.resolution;
    anchored_ = true;
  }
  // The cell holding world point (x, y).
  Cell cellAt(double x, double y) const {
    return {std::lround(std::floor((x - origin_x_) / resolution_)), std::lround(std::floor((y - origin_y_) / resolution_))};
  }
  cv::Point2d centre(const Cell& cell) const {
    return {origin_x_ + (cell.first + 0.5) * resolution_, origin_y_ + (cell.second + 0.5) * resolution_};
  }

 private:
  bool anchored_ = false;
  double origin_x_ = 0.0;
  double origin_y_ = 0.0;
  double resolution_ = 1.0;
};

}  // namespace stereonav
