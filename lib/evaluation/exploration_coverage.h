#pragma once

#include <opencv2/core.hpp>

#include <vector>

#include "occupancy_grid/disparity_tagged_grid.h"
#include "simulator/ground_truth_map.h"

namespace stereonav {

// How much of the world an exploration mapped, judged against the world's ground truth.
struct ExplorationCoverage {
  // Free floor the robot's body can reach from the start: the true free cells a disc of the
  // robot's radius covers somewhere along a collision-free motion from the start.
  double reachable_free_m2 = 0.0;
  // Of those, the area the stereo map holds as free (the map's cell at the same world point).
  double covered_m2 = 0.0;
  double coverage = 0.0;  // covered / reachable
  // Of those, the area the map holds as known at all (free or occupied): what the robot has
  // looked at, right or wrong. covered / seen is the map's quality there, seen / reachable the
  // exploration's reach.
  double seen_m2 = 0.0;
  double seen_coverage = 0.0;  // seen / reachable
  // The map's own view: cells known free or occupied, and known free, anywhere.
  double known_area_m2 = 0.0;
  double free_area_m2 = 0.0;
};

// The true free floor a robot's body can reach from its start: the true free cells a disc of the
// robot's radius covers somewhere along a collision-free motion from the start. Found once per
// world and start; each map of a run is then measured against it.
class ReachableFloor {
 public:
  ReachableFloor(const GroundTruthMap& truth, double robot_radius_m, double start_x, double start_y);

  // The map must be in the world frame (mapped from a start pose equal to the world's, e.g. dead
  // reckoning starting at the true start pose, which then drifts: misplaced cells count as missed).
  ExplorationCoverage measure(const DisparityTaggedGrid& map) const;

 private:
  std::vector<cv::Point2d> cell_centres_;  // world metres
  double cell_area_m2_;
  double area_m2_ = 0.0;
};

}  // namespace stereonav
