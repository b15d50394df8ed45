#include "explorer/safety_guard.h"

#include <mrpt/maps/CSimplePointsMap.h>

#include <algorithm>
#include <cmath>

#include "explorer/free_travel.h"

namespace stereonav {
namespace {

NearObstacleMemoryOptions nearObstacleOptions(const ExplorerOptions& options) {
  NearObstacleMemoryOptions memory;
  memory.remember_within_m = options.obstacle_memory_range_m;
  memory.judge_beyond_m = options.obstacle_memory_blind_m;
  return memory;
}

mrpt::math::TPoint2D composed(const mrpt::poses::CPose2D& pose, const mrpt::math::TPoint2D& local) {
  mrpt::math::TPoint2D global;
  pose.composePoint(local, global);
  return global;
}

// Where what the body touches, or may touch unseen, is remembered: this far beyond its edge.
constexpr double kContactBeyondBody = 0.05;

}  // namespace

SafetyGuard::SafetyGuard(const ExplorerOptions& options)
    : options_(options), near_obstacles_(nearObstacleOptions(options)) {}

const std::vector<mrpt::math::TPoint2D>& SafetyGuard::newestScan() const {
  static const std::vector<mrpt::math::TPoint2D> kNone;
  return recent_scans_.empty() ? kNone : recent_scans_.back().second;
}

double SafetyGuard::reach() const {
  return options_.guard_horizon_m + options_.robot_radius_m + options_.guard_margin_m;
}

void SafetyGuard::readScan(mrpt::nav::CRobot2NavInterface& robot, const mrpt::poses::CPose2D& pose, double time_s,
                           const NavigationGrid* map) {
  while (!recent_scans_.empty() && time_s - recent_scans_.front().first > options_.scan_memory_s) {
    recent_scans_.pop_front();
  }
  mrpt::maps::CSimplePointsMap points;
  mrpt::system::TTimeStamp stamp = INVALID_TIMESTAMP;
  if (!robot.senseObstacles(points, stamp) || stamp == last_scan_stamp_) return;
  last_scan_stamp_ = stamp;
  const double reach = this->reach();
  std::vector<mrpt::math::TPoint2D> local, in_map;
  for (size_t i = 0; i < points.size(); ++i) {
    float x = 0.0f, y = 0.0f, z = 0.0f;
    points.getPoint(i, x, y, z);
    local.emplace_back(x, y);
    if (std::hypot(x, y) <= reach) in_map.push_back(composed(pose, local.back()));
  }
  recent_scans_.emplace_back(time_s, std::move(in_map));
  if (map != nullptr) {
    near_obstacles_.update(local, pose, [&](double x, double y) { return map->mapHoldsObstacle(x, y); });
  }
}

VelocityCommand SafetyGuard::guard(VelocityCommand command, const mrpt::poses::CPose2D& pose,
                                   std::optional<double> path_end_m) {
  free_travel_m_ = options_.guard_horizon_m;
  if (command.speed == 0.0) return command;
  const double reach = this->reach();
  std::vector<mrpt::math::TPoint2D> local;
  const auto add = [&](const mrpt::math::TPoint2D& point) {
    const mrpt::math::TPoint2D robot_frame = pose.inverseComposePoint(point);
    if (std::hypot(robot_frame.x, robot_frame.y) <= reach) local.push_back(robot_frame);
  };
  for (const auto& scan : recent_scans_) {
    for (const mrpt::math::TPoint2D& point : scan.second) add(point);
  }
  for (const mrpt::math::TPoint2D& point : near_obstacles_.pointsNear(pose.x(), pose.y(), reach)) add(point);
  const double radius = options_.robot_radius_m, margin = options_.guard_margin_m;
  const double horizon = options_.guard_horizon_m;
  const FreeTravel free = stereonav::freeTravel(local, radius, margin, command.speed, command.turn_rate, horizon);
  free_travel_m_ = std::min(free.to_contact_m, free.beside_m);
  const auto braking = [&](double travel) {
    return std::sqrt(2.0 * options_.braking_deceleration * std::max(0.0, travel - options_.stop_gap_m));
  };
  const bool fits_at_path_end =
      path_end_m && free.body_contact_m >= *path_end_m + options_.safety_margin_m && command.speed > 0.0;
  const double allowed_to_contact =
      fits_at_path_end ? std::max(braking(free.to_contact_m), options_.pass_beside_speed_mps) : braking(free.to_contact_m);
  const double allowed = std::min(allowed_to_contact, std::max(options_.pass_beside_speed_mps, braking(free.beside_m)));
  if (std::abs(command.speed) <= allowed) return command;
  if (allowed_to_contact < options_.held_speed_mps) {
    std::vector<mrpt::math::TPoint2D> holding;
    for (const mrpt::math::TPoint2D& point : local) {
      // Nothing solid can be under the body: such a point (blind_column_points.h) says that the
      // robot cannot see the ground ahead there. Whatever it cannot see may touch the body, so it
      // is remembered just beyond the body's edge, as a contact is (rememberContact), until a
      // later view sees past it.
      const double range = std::hypot(point.x, point.y);
      if (range < radius) {
        const double scale = (radius + kContactBeyondBody) / std::max(range, 1e-9);
        holding.push_back(composed(pose, {point.x * scale, point.y * scale}));
        continue;
      }
      const double travel =
          stereonav::freeTravel({point}, radius, margin, command.speed, command.turn_rate, horizon).to_contact_m;
      if (travel <= free.to_contact_m + options_.holding_depth_m) holding.push_back(composed(pose, point));
    }
    near_obstacles_.remember(holding);
  }
  command.speed = std::copysign(allowed, command.speed);
  return command;
}

bool SafetyGuard::blocked(double commanded_speed, double speed, double time_s) {
  if (commanded_speed < options_.blocked_command_mps || speed > options_.blocked_speed_mps) {
    blocked_since_ = -1.0;
    return false;
  }
  if (blocked_since_ < 0.0) {
    blocked_since_ = time_s;
    return false;
  }
  return time_s - blocked_since_ >= options_.blocked_s;
}

void SafetyGuard::rememberContact(const mrpt::poses::CPose2D& pose) {
  // Just beyond the body's edge, across its front arc.
  const double reach = options_.robot_radius_m + kContactBeyondBody;
  for (const double bearing : {-0.6, -0.3, 0.0, 0.3, 0.6}) {
    contacts_.emplace_back(pose.x() + reach * std::cos(pose.phi() + bearing),
                           pose.y() + reach * std::sin(pose.phi() + bearing));
  }
}

std::vector<cv::Point2d> SafetyGuard::rememberedObstacles() const {
  std::vector<cv::Point2d> obstacles = contacts_;
  for (const mrpt::math::TPoint2D& point : near_obstacles_.points()) obstacles.emplace_back(point.x, point.y);
  return obstacles;
}

}  // namespace stereonav
