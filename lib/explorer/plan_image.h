#pragma once

#include <opencv2/core.hpp>

#include <vector>

#include "explorer/cost_to_go_field.h"
#include "explorer/frontier_finder.h"
#include "explorer/navigation_grid.h"

namespace stereonav {

// A plan as the explorer sees it, one pixel per cell, top row = max y: obstacles black
// (imprecise ones dark grey), unknown grey, free white, cells where the body fits light green,
// frontier cells blue, remembered near obstacles and contacts red.
cv::Mat3b drawPlan(const NavigationGrid& grid, const CostToGoField& field, const std::vector<Frontier>& frontiers,
                   const std::vector<cv::Point2d>& remembered_obstacles);

}  // namespace stereonav
