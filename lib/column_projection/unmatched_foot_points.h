#pragma once

#include <mrpt/math/TPoint2D.h>

#include <vector>

#include "column_projection/disparity_scan.h"
#include "rig/camera_rig.h"

namespace stereonav {

// What a driver carrying the stereo head reports to a navigator as obstacles
// (mrpt::nav::CRobot2NavInterface::senseObstacles) besides the virtual laser scan's points, where a
// column's floor ends at a surface that matched nothing, nearer than the column's reading
// (DisparityScan::column_clear_end): one point per such column, on the floor where its view of the
// floor ends, robot frame (x ahead, y to the left). The scan's reading there is a textured surface
// seen past a flat-painted one (the window matcher gives the paint's pixels beside it that
// surface's disparity); the map already stops that reading's CLEAR at the foot, and a guard fed
// only the readings would drive into the paint. Empty when the scan holds no such feet.
std::vector<mrpt::math::TPoint2D> unmatchedFootPoints(const DisparityScan& scan, const CameraRig& rig);

}  // namespace stereonav
