#include "occupancy_grid/disparity_scan_inserter.h"

#include <algorithm>
#include <cmath>

namespace stereonav {

DisparityScanInserter::DisparityScanInserter(const SensorModelOptions& sensor_model,
                                             const GridUpdateOptions& update,
                                             double growth_margin_m)
    : model_(sensor_model), update_(update), growth_margin_m_(growth_margin_m) {}

void DisparityScanInserter::insert(const DisparityScan& scan, const DisparityScanCamera& camera,
                                   const mrpt::poses::CPose2D& robot_pose,
                                   DisparityTaggedGrid& grid) {
  const mrpt::poses::CPose2D camera_pose = robot_pose + cameraFloorPose(camera.pose_on_robot);
  model_.readings(scan, camera, readings_);
  if (readings_.empty()) return;
  grid.growToInclude(model_.bounds(readings_, camera_pose), growth_margin_m_);
  // The grid was grown to cover every region; the window only guards against rounding at its
  // border, and it spares the loops below any bounds checks.
  model_.rasterize(readings_, camera_pose, grid.frame(), raster_,
                   CellWindow::grid(grid.width(), grid.height()));

  const CellSpan* spans = raster_.spans.begin();
  // The camera in cell units (cell (c, r) has its centre at c + 0.5, r + 0.5).
  const double camera_col = (camera_pose.x() - grid.minX()) / grid.resolution();
  const double camera_row = (camera_pose.y() - grid.minY()) / grid.resolution();
  clearCells(spans + raster_.clear_begin, raster_.spans.end(), camera_col, camera_row, grid);
  for (const ReadingSpans& reading : raster_.readings) {
    const CellSpan* occupied_begin = spans + reading.occupied_begin;
    const CellSpan* occupied_end = spans + reading.occupied_end;
    if (occupied_begin == occupied_end) continue;
    if (update_.accuracy_preservation &&
        explainedByBetterEvidence(occupied_begin, occupied_end, reading.disparity, grid)) {
      continue;
    }
    const bool from_far = update_.free_preservation_range_m > 0.0 &&
                          camera.depthForDisparity(reading.disparity) >
                              update_.free_preservation_range_m;
    occupyCells(occupied_begin, occupied_end, reading.disparity, from_far, grid);
  }
}

// The cell loops below are written so that the compiler vectorises them over long spans.
void DisparityScanInserter::clearCells(const CellSpan* begin, const CellSpan* end,
                                       double camera_col, double camera_row,
                                       DisparityTaggedGrid& grid) const {
  const int g_min = update_.scale.g_min, step = update_.update_step;
  const double close_cells = update_.free_preservation_range_m / grid.resolution();
  for (const CellSpan* span = begin; span != end; ++span) {
    const int col_begin = span->col_begin, col_end = span->col_end;
    uint8_t* row = grid.occupancyRow(span->row, col_begin, col_end);
    for (int col = col_begin; col < col_end; ++col) {
      row[col] = static_cast<uint8_t>(std::max(row[col] - step, g_min));
    }
    // The cells of this row whose centres lie within the range: one chord of the disc.
    const double dy = span->row + 0.5 - camera_row;
    if (std::abs(dy) >= close_cells) continue;
    const double half_chord = std::sqrt(close_cells * close_cells - dy * dy);
    const int close_begin =
        std::max(col_begin, static_cast<int>(std::ceil(camera_col - half_chord - 0.5)));
    const int close_end =
        std::min(col_end, static_cast<int>(std::floor(camera_col + half_chord - 0.5)) + 1);
    if (close_begin < close_end) {
      uint8_t* close_free = grid.closeFreeRow(span->row, close_begin, close_end);
      std::fill(close_free + close_begin, close_free + close_end, uint8_t{1});
    }
  }
}

bool DisparityScanInserter::explainedByBetterEvidence(const CellSpan* begin, const CellSpan* end,
                                                      float disparity,
                                                      const DisparityTaggedGrid& grid) const {
  const uint8_t unknown = update_.scale.unknown();
  for (const CellSpan* span = begin; span != end; ++span) {
    const int col_begin = span->col_begin, col_end = span->col_end;
    const uint8_t* occupancy = grid.occupancyRow(span->row);
    const float* tags = grid.tagRow(span->row);
    // Spans are a few cells long (most regions are narrow and oblique): a plain loop that stops
    // at the first explaining cell beats a vectorised one.
    for (int col = col_begin; col < col_end; ++col) {
      if (tags[col] > disparity && occupancy[col] > unknown) return true;
    }
  }
  return false;
}

void DisparityScanInserter::occupyCells(const CellSpan* begin, const CellSpan* end,
                                        float disparity, bool spare_close_free,
                                        DisparityTaggedGrid& grid) const {
  const int g_max = update_.scale.g_max, step = update_.update_step;
  // With preservation off no cell is ever marked, so there is nothing to unmark.
  const bool unmark_close_free = update_.free_preservation_range_m > 0.0;
  for (const CellSpan* span = begin; span != end; ++span) {
    const int col_begin = span->col_begin, col_end = span->col_end;
    uint8_t* occupancy = grid.occupancyRow(span->row, col_begin, col_end);
    float* tags = grid.tagRow(span->row, col_begin, col_end);
    uint8_t* close_free = grid.closeFreeRow(span->row, col_begin, col_end);
    if (spare_close_free) {
      for (int col = col_begin; col < col_end; ++col) {
        if (close_free[col]) continue;
        occupancy[col] = static_cast<uint8_t>(std::min(occupancy[col] + step, g_max));
        tags[col] = disparity;
      }
    } else {
      for (int col = col_begin; col < col_end; ++col) {
        occupancy[col] = static_cast<uint8_t>(std::min(occupancy[col] + step, g_max));
        tags[col] = disparity;
      }
      if (unmark_close_free) {
        std::fill(close_free + col_begin, close_free + col_end, uint8_t{0});
      }
    }
  }
}

}  // namespace stereonav
