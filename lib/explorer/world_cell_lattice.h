#pragma once

#include <opencv2/core.hpp>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "occupancy_grid/grid_frame.h"

namespace stereonav {

// Names a grid's cells so that the names survive the grid's growth: a grid grows by whole cells
// (DisparityTaggedGrid::growToInclude), so every cell keeps its place in the lattice anchored at
// the first grid's origin. Rounding a cell centre to a multiple of the resolution would not do:
// with the origin on such a multiple every centre lies half way between two of them.
class WorldCellLattice {
 public:
  using Cell = std::pair<long, long>;

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

// A value per lattice cell, T{} for every cell never set: the memories look cells up for every
// cell in view and every frontier cell, every frame. A box of the cells set so far, grown by
// whole blocks as cells beyond it are set; the floor a robot explores bounds it. (Hash sets and
// trees of a hundred thousand cells cost a cache miss or more per look-up: 3% of a run.)
template <typename T>
class WorldCellMap {
 public:
  using Cell = WorldCellLattice::Cell;

  T get(const Cell& cell) const { return holds(cell) ? values_[indexOf(cell)] : T{}; }
  // The cell's value, to be set.
  T& at(const Cell& cell) {
    include(cell);
    return values_[indexOf(cell)];
  }
  // Whether no cell was ever set (at() was never called).
  bool empty() const { return values_.empty(); }
  void clear() {
    values_.clear();
    cols_ = rows_ = 0;
  }

 private:
  static constexpr long kBlock = 64;  // cells added beyond the one that needs them, each way

  bool holds(const Cell& cell) const {
    const long col = cell.first - first_col_, row = cell.second - first_row_;
    return col >= 0 && row >= 0 && col < cols_ && row < rows_;
  }
  size_t indexOf(const Cell& cell) const {
    return static_cast<size_t>((cell.second - first_row_) * cols_ + cell.first - first_col_);
  }
  void include(const Cell& cell) {
    if (holds(cell)) return;
    long first_col = cell.first - kBlock, first_row = cell.second - kBlock;
    long last_col = cell.first + kBlock, last_row = cell.second + kBlock;
    if (!values_.empty()) {
      first_col = std::min(first_col, first_col_);
      first_row = std::min(first_row, first_row_);
      last_col = std::max(last_col, first_col_ + cols_ - 1);
      last_row = std::max(last_row, first_row_ + rows_ - 1);
    }
    const long cols = last_col - first_col + 1, rows = last_row - first_row + 1;
    std::vector<T> values(static_cast<size_t>(cols * rows), T{});
    for (long r = 0; r < rows_; ++r) {
      std::copy_n(values_.begin() + r * cols_, cols_,
                  values.begin() + (r + first_row_ - first_row) * cols + first_col_ - first_col);
    }
    values_.swap(values);
    first_col_ = first_col;
    first_row_ = first_row;
    cols_ = cols;
    rows_ = rows;
  }

  long first_col_ = 0, first_row_ = 0, cols_ = 0, rows_ = 0;
  std::vector<T> values_;  // row by row
};

}  // namespace stereonav
