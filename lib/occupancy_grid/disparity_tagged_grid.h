#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "occupancy_grid/grid_options.h"
#include "sensor_model/stereo_sensor_model.h"

namespace stereonav {

// The paper's occupancy grid with its second layer (sections 3.4 and 4.3): per cell the
// occupancy value G (see OccupancyScale) and the disparity tag, the disparity of the reading
// that last added OCC evidence to the cell (kNoTag if none did). A third layer marks the cells
// seen free from close (free-space preservation, see DisparityScanInserter). Cell (col, row) covers
// [min_x + col r, min_x + (col+1) r) x [min_y + row r, ...), rows going up in y like MRPT's
// COccupancyGridMap2D, so conversions copy rows one to one. Storage only: the update rule lives
// in DisparityScanInserter.
class DisparityTaggedGrid {
 public:
  static constexpr float kNoTag = -1.0f;

  DisparityTaggedGrid(const GridLimits& limits, const OccupancyScale& scale);

  const GridFrame& frame() const { return frame_; }
  const OccupancyScale& scale() const { return scale_; }
  double resolution() const { return frame_.resolution; }
  int width() const { return width_; }
  int height() const { return height_; }
  double minX() const { return frame_.origin_x; }
  double minY() const { return frame_.origin_y; }
  double maxX() const { return frame_.origin_x + width_ * frame_.resolution; }
  double maxY() const { return frame_.origin_y + height_ * frame_.resolution; }

  bool containsCell(int col, int row) const {
    return col >= 0 && row >= 0 && col < width_ && row < height_;
  }
  // The cell whose square contains world point (x, y); false if outside the grid.
  bool cellAt(double x, double y, int& col, int& row) const;

  uint8_t occupancy(int col, int row) const { return occupancy_[index(col, row)]; }
  float disparityTag(int col, int row) const { return tags_[index(col, row)]; }
  bool closeFree(int col, int row) const { return close_free_[index(col, row)] != 0; }
  const uint8_t* occupancyRow(int row) const { return &occupancy_[index(0, row)]; }
  const float* tagRow(int row) const { return &tags_[index(0, row)]; }
  const uint8_t* closeFreeRow(int row) const { return &close_free_[index(0, row)]; }
  // Rows to write, the whole row or only columns [col_begin, col_end) of it: see writtenCells.
  uint8_t* occupancyRow(int row) { return occupancyRow(row, 0, width_); }
  float* tagRow(int row) { return tagRow(row, 0, width_); }
  uint8_t* closeFreeRow(int row) { return closeFreeRow(row, 0, width_); }
  uint8_t* occupancyRow(int row, int col_begin, int col_end) {
    noteWritten(row, col_begin, col_end);
    return &occupancy_[index(0, row)];
  }
  float* tagRow(int row, int col_begin, int col_end) {
    noteWritten(row, col_begin, col_end);
    return &tags_[index(0, row)];
  }
  uint8_t* closeFreeRow(int row, int col_begin, int col_end) {
    noteWritten(row, col_begin, col_end);
    return &close_free_[index(0, row)];
  }
  // Every cell outside these holds the initial state (unknown, untagged, not close-free): what
  // looks for evidence need look no farther. The grid grows to far readings' bounds plus a
  // margin, and a third of it is never written. Counted from the rows handed out to write, so
  // it may hold cells that were written back to the initial state, or not written at all.
  const CellWindow& writtenCells() const { return written_; }

  // Grows the grid by whole cells on the sides where `bounds` sticks out, by enough to cover it
  // plus `margin_m`; existing cells keep their world coordinates and values. Never shrinks, and
  // never beyond the limits' max_cells (then reachedCellLimit() turns true).
  void growToInclude(const WorldBounds& bounds, double margin_m);
  bool reachedCellLimit() const { return reached_cell_limit_; }

  // Back to the initial limits, all cells unknown, untagged and not close-free.
  void reset(const GridLimits& limits);

  // Direct construction from stored layers (deserialisation); sizes must match.
  void assign(const GridFrame& frame, int width, int height, std::vector<uint8_t> occupancy,
              std::vector<float> tags, std::vector<uint8_t> close_free);
  const std::vector<uint8_t>& occupancyLayer() const { return occupancy_; }
  const std::vector<float>& tagLayer() const { return tags_; }
  const std::vector<uint8_t>& closeFreeLayer() const { return close_free_; }

 private:
  void noteWritten(int row, int col_begin, int col_end) {
    if (col_begin >= col_end) return;
    if (written_.col_begin >= written_.col_end) {
      written_ = {col_begin, col_end, row, row + 1};
      return;
    }
    written_.col_begin = std::min(written_.col_begin, col_begin);
    written_.col_end = std::max(written_.col_end, col_end);
    written_.row_begin = std::min(written_.row_begin, row);
    written_.row_end = std::max(written_.row_end, row + 1);
  }
  size_t index(int col, int row) const {
    return static_cast<size_t>(row) * static_cast<size_t>(width_) + static_cast<size_t>(col);
  }

  OccupancyScale scale_;
  GridFrame frame_;
  int width_ = 0;
  int height_ = 0;
  std::vector<uint8_t> occupancy_;
  std::vector<float> tags_;
  std::vector<uint8_t> close_free_;
  CellWindow written_{0, 0, 0, 0};
  int64_t max_cells_ = 0;
  bool reached_cell_limit_ = false;
};

}  // namespace stereonav
