#pragma once

#include <mrpt/poses/CPose2D.h>

#include <opencv2/core.hpp>

#include <vector>

#include "occupancy_grid/ros_map.h"

namespace stereonav {

// Which parts of a ground-truth map a run could have mapped at all; masks over the truth's cells
// (255 = in, row iy as in RosMap).

// The ground-truth free cells 4-connected to the free cell holding (start_x, start_y): the free
// space a robot starting there can reach (ignoring its size). Throws std::invalid_argument if
// the start is not on a free cell.
cv::Mat1b reachableFreeCells(const RosMap& truth, double start_x, double start_y);

// Ground-truth obstacle cells a forward-looking camera saw from any of `poses`: the first
// obstacle cell along rays from the pose's position, fanned over `fov_deg` about its heading,
// up to `range_m`. Rays are cast in the 2D map (an obstacle hides everything behind it), so
// this is what a perfect range sensor with that field of view would have mapped.
cv::Mat1b obstacleCellsInView(const RosMap& truth, const std::vector<mrpt::poses::CPose2D>& poses,
                              double fov_deg, double range_m);

}  // namespace stereonav
