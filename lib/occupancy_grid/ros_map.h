#pragma once

#include <opencv2/core.hpp>

#include <string>

#include "occupancy_grid/grid_options.h"

namespace stereonav {

// A ROS map_server map (http://wiki.ros.org/map_server#YAML_format) reduced to what its YAML
// says about every cell: free, unknown or occupied. Any map_server map loads, whoever wrote it
// (the simulator's ground truth, `stereonav map`, ROS, MRPT's saveAsBitmapFile + a YAML).
class RosMap {
 public:
  // `classes` row iy holds the cells at y from y_min + iy r (bottom row first, unlike the image).
  RosMap(double resolution, double x_min, double y_min, cv::Mat1b classes);

  double resolution() const { return resolution_; }
  double xMin() const { return x_min_; }  // world coordinates of the lower-left cell's corner
  double yMin() const { return y_min_; }
  int width() const { return classes_.cols; }
  int height() const { return classes_.rows; }
  CellClass cell(int ix, int iy) const { return static_cast<CellClass>(classes_(iy, ix)); }
  // The cell holding world point (x, y); kUnknown outside the map.
  CellClass at(double x, double y) const;

 private:
  double resolution_;
  double x_min_;
  double y_min_;
  cv::Mat1b classes_;  // CellClass values
};

// Reads a map_server YAML and its image (path relative to the YAML's folder): keys image,
// resolution and origin are required; negate (default 0), occupied_thresh (0.65), free_thresh
// (0.196) and mode (trinary | scale; raw is refused) as map_server reads them: a pixel's
// occupancy is (255 - grey) / 255 (grey / 255 with negate 1), occupied above occupied_thresh,
// free below free_thresh, unknown between. A rotated origin (yaw != 0) is refused: map_server
// ignores it too, so such maps would be misplaced. Throws std::runtime_error naming the file
// and the key on bad input.
RosMap loadRosMap(const std::string& yaml_path);

}  // namespace stereonav
