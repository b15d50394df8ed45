#pragma once

#include <mrpt/math/TPoint2D.h>

#include <vector>

namespace stereonav {

// How far the robot's disc (radius `radius_m`, centred on the robot frame's origin) can travel
// along the arc that `speed_mps` and `turn_rate` describe, forwards or backwards, before it
// comes within `margin_m` of one of `obstacles` (robot frame: x ahead, y to the left), split by
// what the bare disc would do there:
//   - to_contact_m: points the bare disc would run into along the arc;
//   - beside_m: points the bare disc passes clear of, less than the margin away (a door jamb: a
//     door 0.8 m wide leaves a body 0.6 m wide 0.1 m each side, no more than the margin, so these
//     may slow the robot but must not hold it).
//   - body_contact_m: where the bare disc first touches any point along the arc, margin or not.
// Each is `horizon_m` when nothing of its kind is in the way that soon. Turning on the spot sweeps
// no new ground: horizon_m. A point already within the margin is judged by the bare disc alone,
// so that the robot may move away from it, and while it lies on the side the robot is moving
// towards it also counts as beside at 0 (the robot creeps until it has passed it); a point
// already under the bare disc stops it (to_contact_m 0) if it lies on the side the robot is
// moving towards, and is ignored if it lies behind.
//
// The reactive layer under the planner: the explorer brakes for what the newest stereo scans
// show, whatever the map says (a table top far views have cleared, paper section 6.1; a person
// walking in, section 3.4).
struct FreeTravel {
  double to_contact_m = 0.0;
  double beside_m = 0.0;
  double body_contact_m = 0.0;
};
FreeTravel freeTravel(const std::vector<mrpt::math::TPoint2D>& obstacles, double radius_m, double margin_m,
                      double speed_mps, double turn_rate, double horizon_m);

}  // namespace stereonav
