#pragma once

#include <mrpt/nav/reactive/CRobot2NavInterface.h>
#include <mrpt/poses/CPose2D.h>

#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "explorer/cost_to_go_field.h"
#include "explorer/explorer_options.h"
#include "explorer/explorer_status.h"
#include "explorer/frontier_finder.h"
#include "explorer/frontier_memory.h"
#include "explorer/goal_selection.h"
#include "explorer/motion_controller.h"
#include "explorer/navigation_grid.h"
#include "explorer/safety_guard.h"
#include "explorer/seen_free_memory.h"
#include "explorer/velocity_command.h"

namespace stereonav {

// Frontier-based exploration (paper section 5) over the stereo occupancy grid. The robot sits
// behind MRPT's reactive-navigation boundary, mrpt::nav::CRobot2NavInterface, so the simulator
// and a real robot driver are interchangeable: each control cycle reads the pose
// (getCurrentPoseAndSpeeds; the map is built in the same frame, the robot's dead reckoning) and
// sends a CVehicleVelCmd_DiffDriven (changeSpeeds).
//
// Every new map (updateMap) rebuilds the cost-to-go towards all frontiers at once, so a plan the
// map invalidates (an obstacle appears on the path, a corridor turns out to be a dead end, a
// frontier closes) is replaced at the next frame without a separate recovery step.
//
// Under the planner a reactive guard (safety_guard.h) reads the robot's sensed obstacles every
// cycle (senseObstacles: the newest stereo scan) and brakes so that the body stops short of them
// and of the obstacles seen up close earlier, which the planner avoids too.
//
// This class is the phase machine; its parts own the rest: SafetyGuard (scans, near obstacles,
// blocked watch), MotionController (how to drive, turn, look around, back off), FrontierMemory
// (cells looking does not resolve) and GoalSelection (which frontier, with its penalties and
// stickiness). When no frontier is reachable it relaxes planning step by step (the recovery
// ladder in recoverUnreachable()) before giving up.
class FrontierExplorer {
 public:
  explicit FrontierExplorer(const ExplorerOptions& options);

  // The newest map, built in the robot's pose frame, and the pose it was last updated at.
  void updateMap(const DisparityTaggedGrid& grid, const mrpt::poses::CPose2D& pose);
  // Obstacle points (map frame) that the map cannot hold, kept as near obstacles
  // (near_obstacle_memory.h) until a later view sees past them: what the stereo head saw nearer
  // than its disparity range (range_top_points.h), which the sensor model leaves out of the map.
  // Given before the map of the same frame, the next plan goes round them.
  void rememberObstacles(const std::vector<mrpt::math::TPoint2D>& points);

  // One control cycle: reads the robot and commands it. False once exploration has finished
  // (the robot has been told to stop); stopReason() says why.
  bool controlStep(mrpt::nav::CRobot2NavInterface& robot);

  bool finished() const { return status_.phase == ExplorerPhase::kFinished; }
  const std::string& stopReason() const { return stop_reason_; }
  const ExplorerStatus& status() const { return status_; }

  // The newest plan (plan_image.h). Empty before the first map.
  cv::Mat3b planImage() const;

 private:
  // How far planning is relaxed, until the next frontier is reached: no frontier was reachable
  // with the safety margin, then with the bare body, then past specks either; last, frontiers
  // are looked at from afar (look_from_afar_m).
  enum class Relaxation { kNone, kBareBody, kBareBodyPastSpecks, kLookFromAfar };

  void replan();
  // The command of one cycle before the blocked watch: backing off, or decided and guarded.
  VelocityCommand command(const mrpt::poses::CPose2D& pose, double speed, double time_s,
                          mrpt::nav::CRobot2NavInterface& robot);
  VelocityCommand decide(const mrpt::poses::CPose2D& pose, double time_s);
  VelocityCommand escape(const mrpt::poses::CPose2D& pose, int col, int row);
  // Where a robot whose own cell the plan does not let it stand in may plan from instead of
  // escaping: the traversable cell beside it nearest its position, if its bare body fits where it is.
  std::optional<cv::Point> besideThePlan(const mrpt::poses::CPose2D& pose, int col, int row) const;
  // Plans where the bare body fits, without the safety margin, until the next frontier is
  // reached; the guard still keeps the robot off what the scans show. False when planning is
  // relaxed already or there is no margin to drop.
  bool relaxToBareBody();
  VelocityCommand recoverUnreachable(const mrpt::poses::CPose2D& pose, double time_s);
  VelocityCommand lookAtFrontier(const mrpt::poses::CPose2D& pose, int col, int row, double time_s);
  VelocityCommand lookAround(const mrpt::poses::CPose2D& pose);
  VelocityCommand backOff(const mrpt::poses::CPose2D& pose);
  VelocityCommand guarded(const VelocityCommand& command, const mrpt::poses::CPose2D& pose,
                          std::optional<double> path_end_m = std::nullopt);
  // Blocked though told to drive: remembers what holds it and starts backing off.
  VelocityCommand onBlocked(const mrpt::poses::CPose2D& pose, const VelocityCommand& guarded_command, double time_s,
                            mrpt::nav::CRobot2NavInterface& robot);
  void finish(const std::string& reason);
  // Frontier `index` was looked at from `pose` without resolving; `whole`: every current cell
  // of it is given up too (unreachable). The next plan chooses afresh.
  void dropFrontier(size_t index, const mrpt::poses::CPose2D& pose, bool whole);

  ExplorerOptions options_;
  CostToGoOptions planner_options_;
  NavigationGridOptions grid_options_;
  SafetyGuard guard_;
  MotionController motion_;
  FrontierMemory frontier_memory_;
  GoalSelection goals_;
  SeenFreeMemory seen_free_;
  std::vector<mrpt::poses::CPose2D> visited_;
  std::unique_ptr<NavigationGrid> grid_;
  std::unique_ptr<CostToGoField> field_;
  // The newest map's frontiers as found, and as planned for (without the dropped cells).
  std::vector<Frontier> map_frontiers_;
  std::vector<Frontier> frontiers_;
  Relaxation relaxation_ = Relaxation::kNone;
  // The memory of near obstacles was pruned to what the map holds (no frontier was reachable),
  // here, and the next map has not come yet.
  bool forgot_here_ = false;
  double forgot_x_ = 0.0;
  double forgot_y_ = 0.0;
  bool awaiting_map_ = false;
  int recovery_restarts_ = 0;
  double last_recovery_restart_s_ = -std::numeric_limits<double>::infinity();
  // Progress watch: the lowest cost-to-go reached and when.
  double best_cost_ = 0.0;
  double best_cost_time_ = 0.0;
  // Spot watch: where the robot has been steering (driving or turning towards a target) since
  // when, and the last cycle it steered. A gap longer than kSteeringGapS means another phase ran.
  static constexpr double kSteeringGapS = 0.5;
  double spot_x_ = 0.0;
  double spot_y_ = 0.0;
  double spot_since_s_ = 0.0;
  double last_steering_s_ = -std::numeric_limits<double>::infinity();
  double phase_start_time_ = 0.0;
  std::optional<cv::Point2d> escape_to_;
  // Escape targets the robot was blocked on the way to, since it last stood where its body fits.
  std::vector<cv::Point2d> failed_escapes_;
  double back_off_until_ = 0.0;
  // How far along its path the robot is to stop, while the cycle's command follows a path.
  std::optional<double> path_end_m_;
  ExplorerStatus status_;
  std::string stop_reason_;
};

}  // namespace stereonav
