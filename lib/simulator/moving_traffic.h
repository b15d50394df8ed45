#pragma once

#include <mrpt/poses/CPose2D.h>

#include <vector>

#include "simulator/world.h"

namespace stereonav {

// The world's moving obstacles as a simulation moves them. Each goes round its path at its speed
// (MovingObstacle::at), but waits while its next position would come within kYieldClearanceM of
// the robot's footprint: a person, or someone pushing a cart, stops for a robot standing in the
// way rather than walk into it. A robot that drives into a moving obstacle still collides.
class MovingTraffic {
 public:
  static constexpr double kYieldClearanceM = 0.1;

  // Every obstacle at the start of its path.
  explicit MovingTraffic(const World& world);

  // Moves the obstacles on by `dt` seconds, each unless that would bring it near the robot (a disc
  // of `robot_radius_m` at `robot_pose`); one already that near moves on (it may only leave).
  void advance(double dt, const mrpt::poses::CPose2D& robot_pose, double robot_radius_m);

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
