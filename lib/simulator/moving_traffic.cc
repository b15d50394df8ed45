#include "simulator/moving_traffic.h"

#include "simulator/footprint_overlap.h"

namespace stereonav {

MovingTraffic::MovingTraffic(const World& world)
    : world_(world), travel_time_s_(world.moving_obstacles.size(), 0.0), waited_s_(world.moving_obstacles.size(), 0.0) {
  for (const MovingObstacle& obstacle : world.moving_obstacles) solids_.push_back(obstacle.at(0.0));
}

void MovingTraffic::advance(double dt, const mrpt::poses::CPose2D& robot_pose, double robot_radius_m) {
  const double keep_away = robot_radius_m + kYieldClearanceM;
  for (size_t i = 0; i < solids_.size(); ++i) {
    const Solid next = world_.moving_obstacles[i].at(travel_time_s_[i] + dt);
    if (solidOverlapsDisc(next, robot_pose.x(), robot_pose.y(), keep_away) &&
        !solidOverlapsDisc(solids_[i], robot_pose.x(), robot_pose.y(), keep_away)) {
      waited_s_[i] += dt;
      continue;
    }
    travel_time_s_[i] += dt;
    solids_[i] = next;
  }
}

}  // namespace stereonav
