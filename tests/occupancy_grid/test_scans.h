#pragma once

#include <mrpt/poses/CPose2D.h>

#include <vector>

#include "column_projection/disparity_scan.h"
#include "occupancy_grid/disparity_tagged_grid.h"
#include "rig/camera_rig.h"
#include "sensor_model/stereo_sensor_model.h"

namespace stereonav::testing {

inline DisparityScan scanOf(std::vector<float> disparities) {
  DisparityScan scan;
  scan.column_disparity = std::move(disparities);
  return scan;
}

// One column, f = 1 px, cx = 0, fB = 4: the column's lines of sight are y = +-x/2 from the
// camera, and depth = 4 / d. On a 1 m grid (cell centres at k + 0.5) with the camera at
// (0.5, 0.5), cell centres sit at integer offsets (X, Y) from the camera. For d = 1.5
// (paper eq. 1: depth in [4/2, 4/1) = [2, 4)):
//   OCC   = {X = 2, 3} x {Y = -1, 0, 1}
//   CLEAR = {(0, 0), (1, 0)}
// (see tests/sensor_model/stereo_sensor_model_test.cc for the boundary cases).
inline DisparityScanCamera unitCamera() {
  DisparityScanCamera camera;
  camera.focal_px = 1.0;
  camera.cx = 0.0;
  camera.baseline_m = 4.0;
  camera.pose_on_robot = CameraRig::opticalPoseOnRobot(0.0, 0.0, 0.5, 0.0, 0.0);
  return camera;
}

inline GridLimits unitLimits(double half_extent = 25.0) {
  GridLimits limits;
  limits.min_x = -half_extent;
  limits.max_x = half_extent;
  limits.min_y = -half_extent;
  limits.max_y = half_extent;
  limits.resolution = 1.0;
  limits.growth_margin_m = 0.0;
  return limits;
}

// The robot at world (0.5 + dx, 0.5 + dy), heading `phi`.
inline mrpt::poses::CPose2D robotAt(double dx, double dy, double phi = 0.0) {
  return {0.5 + dx, 0.5 + dy, phi};
}

// G of the cell whose centre is at offset (X, Y) from (0.5, 0.5).
inline int occupancyAt(const DisparityTaggedGrid& grid, int x, int y) {
  int col = 0, row = 0;
  if (!grid.cellAt(0.5 + x, 0.5 + y, col, row)) return -1;
  return grid.occupancy(col, row);
}
inline float tagAt(const DisparityTaggedGrid& grid, int x, int y) {
  int col = 0, row = 0;
  if (!grid.cellAt(0.5 + x, 0.5 + y, col, row)) return -2.0f;
  return grid.disparityTag(col, row);
}

}  // namespace stereonav::testing
