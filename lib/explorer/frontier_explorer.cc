#include "explorer/frontier_explorer.h"

#include <mrpt/kinematics/CVehicleVelCmd_DiffDriven.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <utility>

#include "explorer/escape_search.h"
#include "explorer/plan_image.h"

namespace stereonav {
namespace {

SeenFreeMemoryOptions seenFreeOptions(const ExplorerOptions& options) {
  SeenFreeMemoryOptions memory;
  memory.range_m = options.seen_free_range_m;
  memory.field_of_view_deg = options.field_of_view_deg;
  memory.body_radius_m = options.robot_radius_m;
  return memory;
}

std::string metres(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

}  // namespace

FrontierExplorer::FrontierExplorer(const ExplorerOptions& options)
    : options_(options),
      guard_(options),
      motion_(options),
      frontier_memory_(options),
      goals_(options),
      seen_free_(seenFreeOptions(options)) {
  planner_options_.body_radius_m = options.robot_radius_m + options.safety_margin_m;
  planner_options_.repulsion_distance_m = options.repulsion_distance_m;
  planner_options_.repulsion_weight = options.repulsion_weight;
  grid_options_.body_radius_m = options.robot_radius_m;
  grid_options_.max_hole_cells = options.max_hole_cells;
  grid_options_.precise_min_disparity = static_cast<float>(options.precise_min_disparity);
  grid_options_.sure_obstacle_g = options.obstacle_memory_min_g;
  // The planner's and the controller's repulsion both end this far from an obstacle.
  grid_options_.distance_horizon_m = options.robot_radius_m + options.safety_margin_m + options.repulsion_distance_m;
  status_.phase = options.initial_look_around ? ExplorerPhase::kLookingAround : ExplorerPhase::kTurning;
}

void FrontierExplorer::updateMap(const DisparityTaggedGrid& grid, const mrpt::poses::CPose2D& pose) {
  if (visited_.empty() ||
      std::hypot(pose.x() - visited_.back().x(), pose.y() - visited_.back().y()) >= options_.visit_spacing_m) {
    visited_.push_back(pose);
  }
  frontier_memory_.anchor(grid.frame());
  if (grid_) goals_.carryTargetOver(*grid_, frontiers_, frontier_memory_);
  seen_free_.update(grid, pose);
  grid_ = std::make_unique<NavigationGrid>(grid, visited_, grid_options_, guard_.rememberedObstacles(),
                                           seen_free_.cells(), std::move(grid_));
  // What the robot remembers now was kept when planning relaxed past specks (recoverUnreachable)
  // or learnt since, the guard having held it there: a post, not a mismatch.
  if (relaxation_ >= Relaxation::kBareBodyPastSpecks) grid_->freeSpecks(options_.speck_cells, guard_.rememberedObstacles());
  map_frontiers_ = findFrontiers(*grid_, options_.min_frontier_cells);
  awaiting_map_ = false;
  frontier_memory_.countCloseViews(*grid_, map_frontiers_, pose);
  frontier_memory_.dropSurfaced(*grid_, map_frontiers_, guard_.newestScan(), pose);
  replan();
}

void FrontierExplorer::rememberObstacles(const std::vector<mrpt::math::TPoint2D>& points) {
  guard_.nearObstacles().remember(points);
}

void FrontierExplorer::replan() {
  frontiers_ = frontier_memory_.withoutDropped(*grid_, map_frontiers_);
  CostToGoOptions planner = planner_options_;
  if (relaxation_ != Relaxation::kNone) planner.body_radius_m = options_.robot_radius_m;
  field_ = std::make_unique<CostToGoField>(*grid_, planner);
  const double look_from_m = relaxation_ == Relaxation::kLookFromAfar ? options_.look_from_afar_m : 0.0;
  field_->compute(goals_.goals(*grid_, *field_, frontiers_, planner.body_radius_m, frontier_memory_, look_from_m));
  status_.frontiers = frontiers_.size();
}

bool FrontierExplorer::controlStep(mrpt::nav::CRobot2NavInterface& robot) {
  if (finished()) {
    robot.stop(false);
    return false;
  }
  mrpt::math::TPose2D pose, odometry;
  mrpt::math::TTwist2D velocity;
  mrpt::system::TTimeStamp stamp;
  std::string frame_id;
  if (!robot.getCurrentPoseAndSpeeds(pose, velocity, stamp, odometry, frame_id)) {
    finish("the robot did not report its pose");
    robot.stop(true);
    return false;
  }
  const double time_s = robot.getNavigationTime();
  const mrpt::poses::CPose2D at(pose);
  guard_.readScan(robot, at, time_s, grid_.get());
  const VelocityCommand command = this->command(at, std::hypot(velocity.vx, velocity.vy), time_s, robot);
  status_.speed_command = command.speed;
  status_.turn_rate_command = command.turn_rate;
  if (finished()) {
    robot.stop(false);
    return false;
  }
  mrpt::kinematics::CVehicleVelCmd_DiffDriven velocity_command;
  velocity_command.lin_vel = command.speed;
  velocity_command.ang_vel = command.turn_rate;
  robot.changeSpeeds(velocity_command);
  return true;
}

VelocityCommand FrontierExplorer::command(const mrpt::poses::CPose2D& pose, double speed, double time_s,
                                          mrpt::nav::CRobot2NavInterface& robot) {
  if (status_.phase == ExplorerPhase::kBackingOff && time_s < back_off_until_) return backOff(pose);
  if (status_.phase == ExplorerPhase::kBackingOff) status_.phase = ExplorerPhase::kTurning;
  path_end_m_.reset();
  const VelocityCommand wanted = decide(pose, time_s);
  const VelocityCommand command = guarded(wanted, pose, path_end_m_);
  if (guard_.blocked(wanted.speed, speed, time_s) && !finished()) return onBlocked(pose, command, time_s, robot);
  return command;
}

VelocityCommand FrontierExplorer::onBlocked(const mrpt::poses::CPose2D& pose, const VelocityCommand& guarded_command,
                                            double time_s, mrpt::nav::CRobot2NavInterface& robot) {
  // Held still though it wants to drive: by the guard (what holds it is remembered already), or
  // by something the body touches that no scan shows.
  if (guarded_command.speed >= options_.blocked_command_mps) {
    robot.sendApparentCollisionEvent();
    guard_.rememberContact(pose);
  }
  // An escape the guard will not let the robot drive (what the scans show disagrees with the
  // map) is not tried again from here: the next escape heads for another cell.
  if (status_.phase == ExplorerPhase::kEscaping && escape_to_) failed_escapes_.push_back(*escape_to_);
  status_.phase = ExplorerPhase::kBackingOff;
  back_off_until_ = time_s + options_.back_off_s;
  guard_.clearBlocked();
  return backOff(pose);
}

VelocityCommand FrontierExplorer::guarded(const VelocityCommand& command, const mrpt::poses::CPose2D& pose,
                                          std::optional<double> path_end_m) {
  const VelocityCommand allowed = guard_.guard(command, pose, path_end_m);
  status_.free_travel_m = guard_.freeTravel();
  return allowed;
}

VelocityCommand FrontierExplorer::backOff(const mrpt::poses::CPose2D& pose) {
  const VelocityCommand reverse = motion_.roomBehind(pose, *grid_) ? guarded(motion_.reverse(), pose) : VelocityCommand{};
  return reverse.speed < 0.0 ? reverse : motion_.turnOnTheSpot();
}

VelocityCommand FrontierExplorer::lookAround(const mrpt::poses::CPose2D& pose) {
  const bool continuing = status_.phase == ExplorerPhase::kLookingAround;
  status_.phase = ExplorerPhase::kLookingAround;
  if (const std::optional<VelocityCommand> turn = motion_.lookAround(pose, continuing)) return *turn;
  status_.phase = ExplorerPhase::kTurning;
  return {};
}

VelocityCommand FrontierExplorer::decide(const mrpt::poses::CPose2D& pose, double time_s) {
  if (!grid_ || awaiting_map_) return {};
  motion_.forgetLookAroundIfMoved(pose);
  if (forgot_here_ && std::hypot(pose.x() - forgot_x_, pose.y() - forgot_y_) > options_.look_around_spacing_m) {
    forgot_here_ = false;
  }
  if (status_.phase == ExplorerPhase::kLookingAround) {
    const VelocityCommand turn = lookAround(pose);
    if (status_.phase == ExplorerPhase::kLookingAround) return turn;
  }
  int col = 0, row = 0;
  if (!grid_->cellAt(pose.x(), pose.y(), col, row)) {
    finish("the robot is outside its own map");
    return {};
  }
  if (!field_->traversable(col, row)) {
    const std::optional<cv::Point> beside = besideThePlan(pose, col, row);
    if (!beside) return escape(pose, col, row);
    col = beside->x;
    row = beside->y;
  }
  if (status_.phase == ExplorerPhase::kEscaping) status_.phase = ExplorerPhase::kTurning;
  escape_to_.reset();
  failed_escapes_.clear();
  if (!field_->reachable(col, row)) return recoverUnreachable(pose, time_s);

  const std::vector<cv::Point> path = field_->pathFrom(col, row);
  const cv::Point2d goal(grid_->centreX(path.back().x), grid_->centreY(path.back().y));
  const std::optional<cv::Point2d>& target = goals_.target();
  // A goal more than a metre from the last is a new target: its progress watch starts afresh.
  if (!target || std::hypot(goal.x - target->x, goal.y - target->y) > 1.0) {
    best_cost_ = field_->cost(col, row);
    best_cost_time_ = time_s;
  }
  goals_.aimAt(goal, field_->label(col, row));
  status_.has_target = true;
  status_.target_x = goal.x;
  status_.target_y = goal.y;
  status_.cost_to_go = field_->cost(col, row);
  if (field_->cost(col, row) - field_->cost(path.back().x, path.back().y) <= options_.arrived_m) {
    return lookAtFrontier(pose, col, row, time_s);
  }
  if (status_.phase == ExplorerPhase::kLookingAtFrontier) status_.phase = ExplorerPhase::kTurning;
  if (status_.cost_to_go < best_cost_ - options_.progress_m) {
    best_cost_ = status_.cost_to_go;
    best_cost_time_ = time_s;
  } else if (time_s - best_cost_time_ > options_.stuck_timeout_s) {
    dropFrontier(static_cast<size_t>(field_->label(col, row)), pose, true);
    best_cost_time_ = time_s;
    return {};
  }
  // That watch starts afresh with each new target, so a target flipping between two frontiers
  // (one that vanishes when faced and comes back when the robot turns away) kept a robot turning
  // on one spot until the time ran out (session 89). Steering without leaving the spot counts
  // whatever the target; any other phase in between (a look, an escape, a back-off) restarts it.
  const bool steered_last_cycle = time_s - last_steering_s_ <= kSteeringGapS;
  last_steering_s_ = time_s;
  if (!steered_last_cycle || std::hypot(pose.x() - spot_x_, pose.y() - spot_y_) > options_.progress_m) {
    spot_x_ = pose.x();
    spot_y_ = pose.y();
    spot_since_s_ = time_s;
  } else if (time_s - spot_since_s_ > options_.stuck_timeout_s) {
    dropFrontier(static_cast<size_t>(field_->label(col, row)), pose, true);
    spot_since_s_ = time_s;
    return {};
  }
  const MotionController::Drive drive =
      motion_.drive(pose, path, *grid_, status_.phase == ExplorerPhase::kDriving);
  status_.phase = drive.driving ? ExplorerPhase::kDriving : ExplorerPhase::kTurning;
  path_end_m_ = drive.path_length_m;
  return drive.command;
}

std::optional<cv::Point> FrontierExplorer::besideThePlan(const mrpt::poses::CPose2D& pose, int col, int row) const {
  // A door a few centimetres wider than the body with its margin is one or two cells of plan
  // wide, and a robot heading into it cuts the corner of its first cell by a few centimetres: an
  // escape back out of the door, and again at each attempt (ini/worlds/door_080.ini).
  if (grid_->clearanceAt(pose.x(), pose.y(), options_.robot_radius_m) < options_.robot_radius_m) return std::nullopt;
  std::optional<cv::Point> nearest;
  double nearest_m = std::numeric_limits<double>::infinity();
  for (int r = row - 1; r <= row + 1; ++r) {
    for (int c = col - 1; c <= col + 1; ++c) {
      if (!field_->traversable(c, r)) continue;
      const double distance = std::hypot(grid_->centreX(c) - pose.x(), grid_->centreY(r) - pose.y());
      if (distance < nearest_m) {
        nearest_m = distance;
        nearest = cv::Point(c, r);
      }
    }
  }
  return nearest;
}

VelocityCommand FrontierExplorer::escape(const mrpt::poses::CPose2D& pose, int col, int row) {
  if (!escape_to_ || status_.phase != ExplorerPhase::kEscaping) {
    escape_to_ = findEscape(*grid_, *field_, col, row, options_.escape_search_m, failed_escapes_,
                            options_.failed_escape_m);
    if (!escape_to_) {
      failed_escapes_.clear();
      if (!motion_.lookedAroundHere()) return lookAround(pose);
      // Nowhere near keeps the margin, as at a start in a narrow passage whose walls stereo
      // cannot match: what the look around mapped free is a few narrow wedges.
      if (relaxToBareBody()) return {};
      finish("boxed in: no cell within " + metres(options_.escape_search_m) +
             " m where the robot's body fits in known free space");
      return {};
    }
    status_.phase = ExplorerPhase::kEscaping;
  }
  return motion_.approach(pose, *escape_to_);
}

bool FrontierExplorer::relaxToBareBody() {
  if (relaxation_ != Relaxation::kNone || options_.safety_margin_m <= 0.0) return false;
  relaxation_ = Relaxation::kBareBody;
  replan();
  return true;
}

VelocityCommand FrontierExplorer::recoverUnreachable(const mrpt::poses::CPose2D& pose, double time_s) {
  if (!motion_.lookedAroundHere()) return lookAround(pose);
  NearObstacleMemory& near_obstacles = guard_.nearObstacles();
  const auto give_up = [&](const std::string& reason) -> VelocityCommand {
    if (!frontier_memory_.beginSecondPass()) {
      finish(frontier_memory_.inSecondPass() ? reason + " (in the second pass over every frontier given up)" : reason);
      return {};
    }
    motion_.forgetLookAround();
    replan();
    return lookAround(pose);
  };
  if (frontiers_.empty() && frontier_memory_.looks() == 0) {
    return give_up("no frontier left: every known free cell borders only known cells");
  } else if (frontiers_.empty()) {
    return give_up("no frontier left: the rest were looked at from up close without resolving (" +
           std::to_string(frontier_memory_.looks()) + " looks)");
  } else if (!forgot_here_ &&
             near_obstacles.forgetUnconfirmed([&](double x, double y) { return grid_->mapHoldsObstacle(x, y); }) > 0) {
    // What closed the way may have been the robot's own memory of near obstacles: a person seen
    // in the same place too often to have been seen gone. Only what the map still holds is kept
    // now; plan again on the next map.
    forgot_here_ = true;
    forgot_x_ = pose.x();
    forgot_y_ = pose.y();
    awaiting_map_ = true;
  } else if (relaxToBareBody()) {
    // Doors seen obliquely come out narrower than they are (their jambs' regions of
    // uncertainty, paper section 3.2).
  } else if (relaxation_ < Relaxation::kBareBodyPastSpecks) {
    // Boxed in by specks: lone obstacle cells amid free space, each inflated by the body's
    // radius, in the gaps beside furniture. Up close they are below the cameras' view, so no
    // look clears them; most are stereo mismatches that repeated. Plan past them, but not past
    // what the body has bumped into, and forget the near obstacles on them; the guard brakes for
    // any the scans show to be real, and those it holds the robot at are kept from then on.
    relaxation_ = Relaxation::kBareBodyPastSpecks;
    grid_->freeSpecks(options_.speck_cells, guard_.contacts());
    near_obstacles.forgetUnconfirmed([&](double x, double y) {
      int c = 0, r = 0;
      return !grid_->cellAt(x, y, c, r) || grid_->cellClass(c, r) != NavigationGrid::kFree;
    });
    map_frontiers_ = findFrontiers(*grid_, options_.min_frontier_cells);
    replan();
  } else if (relaxation_ == Relaxation::kBareBodyPastSpecks && options_.look_from_afar_m > 0.0) {
    // Nothing reachable even so: look at each frontier from the nearest place the body reaches,
    // one at a time; what a closer view does not open is given up (lookAtFrontier).
    relaxation_ = Relaxation::kLookFromAfar;
    replan();
  } else if (recovery_restarts_ < options_.recovery_restarts &&
             time_s - last_recovery_restart_s_ >= options_.recovery_restart_spacing_s) {
    // Give up only on what is still unreachable after a fresh look: see recovery_restarts.
    ++recovery_restarts_;
    last_recovery_restart_s_ = time_s;
    motion_.forgetLookAround();
    forgot_here_ = false;
    relaxation_ = Relaxation::kNone;
    replan();
    return lookAround(pose);
  } else {
    size_t cells = 0;
    for (const Frontier& frontier : frontiers_) cells += frontier.cells.size();
    return give_up("no reachable frontier left: " + std::to_string(frontiers_.size()) + " frontier(s) of " + std::to_string(cells) +
           " cells lie beyond gaps narrower than the robot or across unknown space, none within " +
           metres(options_.look_from_afar_m) + " m of where the robot can go");
  }
  return {};
}

VelocityCommand FrontierExplorer::lookAtFrontier(const mrpt::poses::CPose2D& pose, int col, int row, double time_s) {
  // Arrived: face the nearest cell of the frontier, hold for the map to catch up, and if the
  // frontier is still there (unknown behind something stereo cannot resolve), drop it.
  const size_t label = static_cast<size_t>(field_->label(col, row));
  cv::Point nearest_cell;
  double nearest_sq = std::numeric_limits<double>::infinity();
  for (const cv::Point& cell : frontiers_[label].cells) {
    const double dx = grid_->centreX(cell.x) - pose.x(), dy = grid_->centreY(cell.y) - pose.y();
    if (dx * dx + dy * dy < nearest_sq) {
      nearest_sq = dx * dx + dy * dy;
      nearest_cell = cell;
    }
  }
  const cv::Point2d nearest(grid_->centreX(nearest_cell.x), grid_->centreY(nearest_cell.y));
  if (status_.phase != ExplorerPhase::kLookingAtFrontier) {
    status_.phase = ExplorerPhase::kLookingAtFrontier;
    phase_start_time_ = std::numeric_limits<double>::infinity();
  }
  if (!motion_.faces(pose, nearest.x, nearest.y) && nearest_sq > 1e-6) {
    return motion_.turnTowards(pose, nearest.x, nearest.y);
  }
  phase_start_time_ = std::min(phase_start_time_, time_s);
  if (time_s - phase_start_time_ >= options_.look_hold_s) {
    // The faced cell goes in any case, so that every look makes progress.
    frontier_memory_.drop(*grid_, nearest_cell);
    dropFrontier(label, pose, nearest_sq < 1e-6 || relaxation_ == Relaxation::kLookFromAfar);
    status_.phase = ExplorerPhase::kTurning;
  }
  return {};
}

void FrontierExplorer::dropFrontier(size_t index, const mrpt::poses::CPose2D& pose, bool whole) {
  frontier_memory_.lookedFrom(pose);
  if (whole) {
    for (const cv::Point& cell : frontiers_[index].cells) frontier_memory_.drop(*grid_, cell);
  }
  goals_.clear();
  relaxation_ = Relaxation::kNone;
  replan();
}

void FrontierExplorer::finish(const std::string& reason) {
  status_.phase = ExplorerPhase::kFinished;
  status_.has_target = false;
  stop_reason_ = reason;
}

cv::Mat3b FrontierExplorer::planImage() const {
  if (!grid_) return {};
  return drawPlan(*grid_, *field_, frontiers_, guard_.rememberedObstacles());
}

}  // namespace stereonav
