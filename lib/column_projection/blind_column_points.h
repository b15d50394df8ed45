#pragma once

#include <mrpt/math/TPoint2D.h>

#include <vector>

#include "column_projection/disparity_scan.h"
#include "rig/camera_rig.h"

namespace stereonav {

// What a driver carrying the stereo head reports to a navigator as obstacles
// (mrpt::nav::CRobot2NavInterface::senseObstacles) besides the virtual laser scan's points
// (virtual_range_scan.h) when it cannot see where the robot is going: when most of the columns
// whose nearest floor lies ahead of a body of radius body_radius_m (no farther to either side
// than the radius) are blind (DisparityScan::column_blind), one point per such blind column, robot
// frame (x ahead, y to the left), on that floor's bearing just inside the body's front; otherwise
// none. Something the matcher cannot see stands somewhere between the body and that floor, maybe
// touching the body: a guard that stops the body before it moves towards a point under it
// (explorer/free_travel.h) lets the robot turn or back away, but not drive on until it sees the
// floor ahead again. Columns whose nearest floor lies to the side are left out: the body does not
// drive onto it, and near the image's left and right borders the matcher cannot match the floor
// at all (one camera, or the left-right check, does not see every candidate there).
std::vector<mrpt::math::TPoint2D> blindColumnPoints(const DisparityScan& scan, const CameraRig& rig,
                                                    double body_radius_m);

}  // namespace stereonav
