#pragma once

#include <algorithm>
#include <cstdint>

#include "occupancy_grid/disparity_tagged_grid.h"

namespace stereonav {

// Hand-drawn grids: every cell unknown, then rectangles of cells set free or occupied. Cell
// (col, row) spans [col r, (col+1) r) x [row r, (row+1) r) from the origin (0, 0).
class TestGrid {
 public:
  static constexpr uint8_t kFreeG = 0;
  static constexpr uint8_t kOccupiedG = 255;

  TestGrid(int cols, int rows, double resolution = 0.1)
      : grid_(GridLimits{0.0, cols * resolution, 0.0, rows * resolution, resolution, 1.0}, OccupancyScale{}) {}

  // Cells col0..col1, row0..row1 inclusive.
  TestGrid& fill(int col0, int row0, int col1, int row1, uint8_t g) {
    for (int row = row0; row <= row1; ++row) {
      uint8_t* cells = grid_.occupancyRow(row, col0, col1 + 1);
      std::fill(cells + col0, cells + col1 + 1, g);
    }
    return *this;
  }
  TestGrid& free(int col0, int row0, int col1, int row1) { return fill(col0, row0, col1, row1, kFreeG); }
  TestGrid& occupied(int col0, int row0, int col1, int row1) { return fill(col0, row0, col1, row1, kOccupiedG); }
  TestGrid& unknown(int col0, int row0, int col1, int row1) {
    return fill(col0, row0, col1, row1, grid_.scale().unknown());
  }

  // Disparity tags (the reading that last added OCC evidence).
  TestGrid& tag(int col0, int row0, int col1, int row1, float disparity) {
    for (int row = row0; row <= row1; ++row) {
      float* tags = grid_.tagRow(row, col0, col1 + 1);
      std::fill(tags + col0, tags + col1 + 1, disparity);
    }
    return *this;
  }

  const DisparityTaggedGrid& grid() const { return grid_; }

 private:
  DisparityTaggedGrid grid_;
};

}  // namespace stereonav
