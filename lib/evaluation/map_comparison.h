#pragma once

#include <opencv2/core.hpp>

#include "evaluation/map_score.h"
#include "occupancy_grid/ros_map.h"

namespace stereonav {

// A map and its ground truth laid over the truth's cells (masks, 255 = set, row iy as in
// RosMap): what scoreMap counts and drawScoreOverlay shows.
struct MapComparison {
  cv::Mat1b map_occupied;     // the map calls the cell occupied (inside the truth's bounds)
  cv::Mat1b map_free;         // the map calls the cell free (inside the truth's bounds)
  cv::Mat1b truth_occupied;   // a true obstacle
  cv::Mat1b scored_obstacles; // the true obstacles recall and false free count (in view, if poses)
  cv::Mat1b near_truth_obstacle;  // within the tolerance of a true obstacle
  cv::Mat1b near_map_obstacle;    // within the tolerance of a map-occupied cell
  cv::Mat1b free_space;       // the true free cells coverage counts
  bool coverage_from_start = false;
};

// The map is read at the centre of every truth cell; see MapScoreOptions for the rest.
// Throws std::invalid_argument if the start is not free in the truth or the tolerance is negative.
MapComparison compareOnTruthCells(const RosMap& map, const RosMap& truth, const MapScoreOptions& options);

}  // namespace stereonav
