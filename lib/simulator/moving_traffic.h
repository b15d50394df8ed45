#pragma once

#include <mrpt/poses/CPose2D.h>

#include <vector>

#include "simulator/world.h"

namespace stereonav {

// The world's moving obstacles as a simulation moves them. Each goes round its path at its speed
// (MovingObstacle::at), but does not move closer to the robot once its next position would be
// within kYieldClearanceM of the robot's footprint, where it is or where it will be within
// kAnticipationS at its present speed: a person, or someone pushing a cart, stops for a robot in
// the way and does not step in front of a moving one, but walks away from one that came close. A
// robot that drives into a moving obstacle still collides.
class MovingTraffic {
 public:
  // People keep their distance from a robot; it also keeps them out of the rig's blind zone (f B /
  // max_disparity in front of the cameras, about 0.3 m from the body's front).
  static constexpr double kYieldClearanceM = 0.4;
  static constexpr double kAnticipationS = 1.0;

  // Every obstacle at the start of its path.
  explicit MovingTraffic(const World& world);

  // Moves the obstacles on by `dt` seconds, each unless that would bring it near the robot (a disc
  // of `robot_radius_m` at `robot_pose`, or ahead along its heading as far as `robot_speed_mps`
  // takes it in kAnticipationS) and closer to it than it is.
  void advance(double dt, const mrpt::poses::CPose2D& robot_pose, double robot_speed_mps, double robot_radius_m);

  // The obstacles where they are now, in World::moving_obstacles order.
  const std::vector<Solid>& solids() const { return solids_; }
  // Seconds each obstacle has spent waiting for the robot.
  const std::vector<double>& waitedS() const { return waited_s_; }

 private:
  const World& world_;
  std::vector<double> travel_time_s_;
  std::vector<double> waited_s_;
  std::vector<Solid> solids_;
};

}  // namespace stereonav
