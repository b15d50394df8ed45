#pragma once

#include <opencv2/core.hpp>

#include "occupancy_grid/disparity_tagged_grid.h"
#include "sensor_model/stereo_sensor_model.h"

namespace stereonav {

// For every cell of an occupancy grid, the distance from its centre to the centre of the nearest
// cell the grid calls occupied (OccupancyScale::classify), capped at max_distance_m: what a scan
// matcher looks up to see how well a reading lands on the map (a likelihood field).
class ObstacleDistanceField {
 public:
  ObstacleDistanceField(const DisparityTaggedGrid& grid, double max_distance_m);

  // Bilinear between cell centres; max_distance_m outside the grid.
  double distance(double x, double y) const;
  double maxDistance() const { return max_distance_m_; }
  bool hasObstacles() const { return has_obstacles_; }

 private:
  GridFrame frame_;
  double max_distance_m_;
  bool has_obstacles_ = false;
  cv::Mat1f distance_m_;  // row = grid row (y up), col = grid col
};

}  // namespace stereonav
