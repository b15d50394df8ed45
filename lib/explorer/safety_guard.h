#pragma once

#include <mrpt/math/TPoint2D.h>
#include <mrpt/nav/reactive/CRobot2NavInterface.h>
#include <mrpt/poses/CPose2D.h>

#include <opencv2/core.hpp>

#include <deque>
#include <optional>
#include <utility>
#include <vector>

#include "explorer/explorer_options.h"
#include "explorer/navigation_grid.h"
#include "explorer/near_obstacle_memory.h"
#include "explorer/velocity_command.h"

namespace stereonav {

// The reactive layer under the planner: whatever the map says, the body stops short of what the
// robot's newest stereo scans show (CRobot2NavInterface::senseObstacles) and of the obstacles
// it has seen up close before (near_obstacle_memory.h); and a robot told to drive that does not
// move is found blocked. Owns the recent scans, the near-obstacle memory and the contacts.
class SafetyGuard {
 public:
  explicit SafetyGuard(const ExplorerOptions& options);

  // Reads the robot's scan if it is a new one: its points within the guard's reach are kept for
  // scan_memory_s, and the near-obstacle memory learns from it (confirmed by `map`, if any).
  void readScan(mrpt::nav::CRobot2NavInterface& robot, const mrpt::poses::CPose2D& pose, double time_s,
                const NavigationGrid* map);

  // `command` slowed so that the body, widened by guard_margin_m, can brake to a stop stop_gap_m
  // short of the sensed and remembered obstacles it would run into along its arc
  // (free_travel.h); what it would pass clear of but within the margin slows it to
  // pass_beside_speed_mps at most. A command held below held_speed_mps remembers what holds it as
  // near obstacles.
  // `path_end_m`: how far along its path the robot will stop anyway (the plan's goal). Where the
  // bare body, stopping there, is at least the planner's safety_margin_m short of what it would
  // touch along the arc, the robot may creep the rest of the way at pass_beside_speed_mps: the
  // stop gap is room to brake from speed, and the planner's goals near a frontier lie nearer
  // obstacles than the gap (a goal by a door jamb).
  VelocityCommand guard(VelocityCommand command, const mrpt::poses::CPose2D& pose,
                        std::optional<double> path_end_m = std::nullopt);
  // The free travel along the last guarded command's arc (guard_horizon_m when nothing is in the
  // way, or for a command that does not move).
  double freeTravel() const { return free_travel_m_; }

  // True once the robot has been commanded at least blocked_command_mps forward while moving no
  // faster than blocked_speed_mps for blocked_s; clearBlocked() starts the watch again.
  bool blocked(double commanded_speed, double speed, double time_s);
  void clearBlocked() { blocked_since_ = -1.0; }
  // Whatever stops the body lies on its front arc: remembered as obstacles there.
  void rememberContact(const mrpt::poses::CPose2D& pose);

  // The newest scan's points within the guard's reach (map frame).
  const std::vector<mrpt::math::TPoint2D>& newestScan() const;

  // What the planner must also treat as obstacles: the contacts and the near obstacles.
  std::vector<cv::Point2d> rememberedObstacles() const;
  const std::vector<cv::Point2d>& contacts() const { return contacts_; }
  NearObstacleMemory& nearObstacles() { return near_obstacles_; }
  const NearObstacleMemory& nearObstacles() const { return near_obstacles_; }

 private:
  double reach() const;

  ExplorerOptions options_;
  // Obstacle points (map frame) of the recent scans within reach(), by the time they were read.
  std::deque<std::pair<double, std::vector<mrpt::math::TPoint2D>>> recent_scans_;
  mrpt::system::TTimeStamp last_scan_stamp_ = INVALID_TIMESTAMP;
  NearObstacleMemory near_obstacles_;
  std::vector<cv::Point2d> contacts_;
  double free_travel_m_ = 0.0;
  double blocked_since_ = -1.0;
};

}  // namespace stereonav
