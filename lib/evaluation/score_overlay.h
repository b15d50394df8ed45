#pragma once

#include <opencv2/core.hpp>

#include <string>

#include "evaluation/map_score.h"
#include "occupancy_grid/ros_map.h"

namespace stereonav {

// A picture of what scoreMap counted, one pixel per ground-truth cell, top row = max y (as the
// map images): outside the truth's bounds grey; true free space white, light green where the
// map calls it free; true obstacles black where recall found them, blue where it missed them,
// dark grey where they do not count (out of view); map-occupied cells green when within the
// tolerance of a true obstacle, red when not; magenta: a counted true obstacle the map calls free.
cv::Mat3b drawScoreOverlay(const RosMap& map, const RosMap& truth, const MapScoreOptions& options);

// drawScoreOverlay written (atomically) to `path`, format from its extension.
void saveScoreOverlay(const RosMap& map, const RosMap& truth, const MapScoreOptions& options,
                      const std::string& path);

}  // namespace stereonav
