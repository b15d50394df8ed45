#include "occupancy_grid/disparity_scan_inserter.h"

#include <algorithm>

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
  clearCells(spans + raster_.clear_begin, raster_.spans.end(), grid);
  for (const ReadingSpans& reading : raster_.readings) {
    const CellSpan* occupied_begin = spans + reading.occupied_begin;
    const CellSpan* occupied_end = spans + reading.occupied_end;
    if (occupied_begin == occupied_end) continue;
    if (update_.accuracy_preservation &&
        explainedByBetterEvidence(occupied_begin, occupied_end, reading.disparity, grid)) {
      continue;
    }
    occupyCells(occupied_begin, occupied_end, reading.disparity, grid);
  }
}

// The cell loops below are written so that the compiler vectorises them over long spans.
void DisparityScanInserter::clearCells(const CellSpan* begin, const CellSpan* end,
                                       DisparityTaggedGrid& grid) const {
  const int g_min = update_.scale.g_min, step = update_.update_step;
  for (const CellSpan* span = begin; span != end; ++span) {
    const int col_begin = span->col_begin, col_end = span->col_end;
    uint8_t* row = grid.occupancyRow(span->row);
    for (int col = col_begin; col < col_end; ++col) {
      row[col] = static_cast<uint8_t>(std::max(row[col] - step, g_min));
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
                                        float disparity, DisparityTaggedGrid& grid) const {
  const int g_max = update_.scale.g_max, step = update_.update_step;
  for (const CellSpan* span = begin; span != end; ++span) {
    const int col_begin = span->col_begin, col_end = span->col_end;
    uint8_t* occupancy = grid.occupancyRow(span->row);
    float* tags = grid.tagRow(span->row);
    for (int col = col_begin; col < col_end; ++col) {
      occupancy[col] = static_cast<uint8_t>(std::min(occupancy[col] + step, g_max));
      tags[col] = disparity;
    }
  }
}

}  // namespace stereonav
