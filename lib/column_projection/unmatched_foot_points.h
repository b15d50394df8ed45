#pragma once

#include <mrpt/math/TPoint2D.h>

#include <vector>

#include "column_projection/disparity_scan.h"
#include "rig/camera_rig.h"

namespace stereonav {

// What a driver carrying the stereo head reports to a navigator as obstacles
// (mrpt::nav::CRobot2NavInterface::senseObstacles) besides the virtual laser scan's points, where a
// column's floor ends at a surface that matched nothing (DisparityScan::column_clear_end): one
// point per such column, on the floor where its view of the floor ends, robot frame (x ahead, y to
// the left). A flat-painted wall leaves no reading of its own: its columns read nothing, or a
// textured surface seen past it (the window matcher gives the paint's pixels beside that surface
// its disparity). The floor's end is the only sign of it, and a guard fed only the readings drives
// into the paint. Empty when the scan holds no such feet.
std::vector<mrpt::math::TPoint2D> unmatchedFootPoints(const DisparityScan& scan, const CameraRig& rig);

}  // namespace stereonav
