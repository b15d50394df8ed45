#pragma once

#include <mrpt/math/TPoint2D.h>

#include <vector>

#include "column_projection/disparity_scan.h"
#include "rig/camera_rig.h"

namespace stereonav {

// The points of the columns read at the top of the matcher's disparity range
// (DisparityScan::atRangeTop), robot frame (x ahead, y to the left), each where its reading puts
// it: on the column's bearing at depth f B / range_top. Something is there or nearer, so the
// sensor model leaves such columns out of the map (their depth is only a bound), but a navigator
// must keep them as obstacles: nothing else holds a wall or pole that the robot first saw closer
// than the matcher's range. Empty when the scan does not carry its range top or column_row.
std::vector<mrpt::math::TPoint2D> rangeTopPoints(const DisparityScan& scan, const CameraRig& rig);

}  // namespace stereonav
