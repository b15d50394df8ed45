#pragma once

#include <opencv2/core.hpp>

#include <optional>
#include <vector>

#include "explorer/cost_to_go_field.h"
#include "explorer/navigation_grid.h"

namespace stereonav {

// When the map closes in on the robot (a moving obstacle came close, or a better view put a wall
// nearer) the robot at cell (col, row) is no longer where its body fits. The nearest cell where
// it does (field.traversable), reached over known free cells only (4-connected) within
// search_m, and not within failed_m of an escape the robot could not drive to (`failed`).
std::optional<cv::Point2d> findEscape(const NavigationGrid& grid, const CostToGoField& field, int col, int row,
                                      double search_m, const std::vector<cv::Point2d>& failed, double failed_m);

}  // namespace stereonav
