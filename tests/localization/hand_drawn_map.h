#pragma once

// Test scenes drawn by hand as wall segments: the grid they make and the range scans a robot in
// them takes, both computed from the segments directly.

#include <mrpt/core/bits_math.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPose3D.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "occupancy_grid/disparity_tagged_grid.h"

namespace stereonav::testing {

struct Segment {
  double x0, y0, x1, y1;
};

// A grid over [min, max]^2 at `resolution` with the cells the segments pass through occupied
// (G = 255) and every other cell free (G = 0). Cell boundaries lie on multiples of the
// resolution (DisparityTaggedGrid), so a wall drawn halfway between two lies on its cells' centres.
inline DisparityTaggedGrid drawGrid(const std::vector<Segment>& walls, double min_xy, double max_xy,
                                    double resolution) {
  GridLimits limits;
  limits.min_x = limits.min_y = min_xy;
  limits.max_x = limits.max_y = max_xy;
  limits.resolution = resolution;
  DisparityTaggedGrid grid(limits, OccupancyScale{});
  for (int row = 0; row < grid.height(); ++row) std::fill_n(grid.occupancyRow(row), grid.width(), 0);
  for (const Segment& wall : walls) {
    const double length = std::hypot(wall.x1 - wall.x0, wall.y1 - wall.y0);
    const int samples = static_cast<int>(std::ceil(length / (resolution / 4))) + 1;
    for (int k = 0; k < samples; ++k) {
      const double t = static_cast<double>(k) / (samples - 1);
      int col, row;
      if (grid.cellAt(wall.x0 + t * (wall.x1 - wall.x0), wall.y0 + t * (wall.y1 - wall.y0), col, row)) {
        grid.occupancyRow(row)[col] = 255;
      }
    }
  }
  return grid;
}

// A scan of `rays` rays over `aperture_deg`, counter-clockwise, from a sensor at the robot's
// centre: each ray's range to the nearest wall it meets, invalid beyond max_range_m.
inline mrpt::obs::CObservation2DRangeScan scanOf(const std::vector<Segment>& walls,
                                                 const mrpt::poses::CPose2D& robot, size_t rays = 160,
                                                 double aperture_deg = 90.0, double max_range_m = 8.0) {
  mrpt::obs::CObservation2DRangeScan scan;
  scan.aperture = static_cast<float>(mrpt::DEG2RAD(aperture_deg));
  scan.rightToLeft = true;
  scan.maxRange = static_cast<float>(max_range_m);
  scan.sensorPose = mrpt::poses::CPose3D();
  scan.resizeScanAndAssign(rays, scan.maxRange, false);
  for (size_t ray = 0; ray < rays; ++ray) {
    const double angle = robot.phi() + scan.getScanAngle(ray);
    const double dx = std::cos(angle), dy = std::sin(angle);
    double nearest = std::numeric_limits<double>::infinity();
    for (const Segment& wall : walls) {
      // robot + r (dx, dy) = wall start + s (wall end - wall start), 0 <= s <= 1, r > 0.
      const double ex = wall.x1 - wall.x0, ey = wall.y1 - wall.y0;
      const double denominator = dx * ey - dy * ex;
      if (std::abs(denominator) < 1e-12) continue;
      const double wx = wall.x0 - robot.x(), wy = wall.y0 - robot.y();
      const double r = (wx * ey - wy * ex) / denominator;
      const double s = (wx * dy - wy * dx) / denominator;
      if (r > 0.0 && s >= 0.0 && s <= 1.0) nearest = std::min(nearest, r);
    }
    if (nearest <= max_range_m) {
      scan.setScanRange(ray, static_cast<float>(nearest));
      scan.setScanRangeValidity(ray, true);
    }
  }
  return scan;
}

}  // namespace stereonav::testing
