#pragma once

#include <opencv2/core.hpp>

#include <string>

#include "common/ini_section.h"
#include "simulator/world.h"

namespace stereonav {

struct GroundTruthMapOptions {
  double resolution_m = 0.05;
  // The robot's body height band: obstacles that reach into it block the robot (section 3.3).
  double band_min_z = 0.0;
  double band_max_z = 1.0;
  // Unknown cells around the world's bounds, so the map shows where the world ends.
  double margin_m = 0.5;
  // Bound on the map's cells (one byte each); a larger world needs it raised.
  int max_cells = 16'000'000;
};

// Section [ground_truth_map]: resolution_m, margin_m. The height band is the robot's, set by the
// caller (the simulated robot's height_m).
GroundTruthMapOptions loadGroundTruthMapOptions(IniSection& section);

// The true occupancy of a World's static solids for a robot of a given height, on a grid with
// the trinary values of a ROS map_server image.
class GroundTruthMap {
 public:
  static constexpr uint8_t kOccupied = 0;
  static constexpr uint8_t kFree = 254;
  static constexpr uint8_t kUnknown = 205;

  // A cell is occupied when a solid in the band overlaps its interior, free when it lies inside
  // the world's bounds and no solid does, unknown outside the bounds.
  GroundTruthMap(const World& world, const GroundTruthMapOptions& options);

  double resolution() const { return resolution_; }
  double xMin() const { return x_min_; }  // world coordinates of the lower-left cell's corner
  double yMin() const { return y_min_; }
  int width() const { return cells_.cols; }
  int height() const { return cells_.rows; }
  // Cell (ix, iy) spans [xMin + ix r, xMin + (ix + 1) r) x [yMin + iy r, yMin + (iy + 1) r).
  uint8_t cell(int ix, int iy) const { return cells_(iy, ix); }

  // Writes `yaml_path` and the image next to it (same name, .pgm), each atomically: a map that
  // ROS map_server (and mrpt::maps::COccupancyGridMap2D::loadFromROSMapServerYAML) loads.
  void writeRosMap(const std::string& yaml_path) const;

 private:
  double resolution_;
  double x_min_;
  double y_min_;
  cv::Mat1b cells_;  // row iy = cells at y from yMin + iy r (the image is flipped when written)
};

}  // namespace stereonav
