#include "simulator/moving_traffic.h"

#include <mrpt/math/TPoint2D.h>

#include <algorithm>
#include <cmath>

#include "simulator/footprint_overlap.h"

namespace stereonav {

MovingTraffic::MovingTraffic(const World& world)
    : world_(world), travel_time_s_(world.moving_obstacles.size(), 0.0), waited_s_(world.moving_obstacles.size(), 0.0) {
  for (const MovingObstacle& obstacle : world.moving_obstacles) solids_.push_back(obstacle.at(0.0));
}

void MovingTraffic::advance(double dt, const mrpt::poses::CPose2D& robot_pose, double robot_speed_mps,
                            double robot_radius_m) {
  const double keep_away = robot_radius_m + kYieldClearanceM;
  // The robot's footprint now and ahead, in steps shorter than its radius.
  const double ahead = std::max(0.0, robot_speed_mps) * kAnticipationS;
  const int steps = static_cast<int>(std::ceil(ahead / robot_radius_m));
  std::vector<mrpt::math::TPoint2D> footprints;
  for (int k = 0; k <= steps; ++k) {
    const double along = steps == 0 ? 0.0 : ahead * k / steps;
    footprints.emplace_back(robot_pose.x() + along * std::cos(robot_pose.phi()),
                            robot_pose.y() + along * std::sin(robot_pose.phi()));
  }
  const auto near = [&](const Solid& solid, double radius) {
    for (const mrpt::math::TPoint2D& centre : footprints) {
      if (solidOverlapsDisc(solid, centre.x, centre.y, radius)) return true;
    }
    return false;
  };
  for (size_t i = 0; i < solids_.size(); ++i) {
    const Solid next = world_.moving_obstacles[i].at(travel_time_s_[i] + dt);
    const bool closer = std::hypot(next.x - robot_pose.x(), next.y - robot_pose.y()) <
                        std::hypot(solids_[i].x - robot_pose.x(), solids_[i].y - robot_pose.y());
    if (closer && near(next, keep_away)) {
      waited_s_[i] += dt;
      continue;
    }
    travel_time_s_[i] += dt;
    solids_[i] = next;
  }
}

}  // namespace stereonav
