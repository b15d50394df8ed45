#include "explorer/frontier_explorer.h"

#include <mrpt/kinematics/CVehicleVelCmd_DiffDriven.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/math/wrap2pi.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>

#include "explorer/free_travel.h"
#include "explorer/line_of_sight.h"

namespace stereonav {
namespace {

// Facing counts as done within this heading error; turning on the spot never goes slower than
// kMinTurnRate, so it ends.
constexpr double kFacedRad = 0.2;
constexpr double kMinTurnRate = 0.25;
// Turning on the spot plans to brake at this rate (rad/s^2), within what robots like the paper's
// manage (the simulated one: 4).
constexpr double kTurnBraking = 3.0;
// After facing a frontier the robot holds still this long so that the map sees what is behind it
// before the frontier is judged: taking a cell that far readings saturated (255) below the free
// threshold (50) takes eleven CLEAR updates of K = 20 (paper section 3.4), twelve frames at 5 Hz.
// A frontier that resolves sooner ends the look at once (the next plan has another target).
constexpr double kLookHoldS = 2.4;
// The same holds for a frontier cell the robot merely passes in plain sight, a view per map:
// after this many views up close that did not resolve it, it is dropped. Without this the edges
// of what stereo cannot resolve (under a table top, a wall eroded by grazing rays and rebuilt by
// far readings) flicker back as new frontier cells, and the robot tours a finished room.
constexpr int kResolvingViews = 12;
// Progress: the cost-to-go must drop by this much within stuck_timeout_s.
constexpr double kProgressM = 0.3;
// A robot that has moved this far from its last look-around may look around again.
constexpr double kLookAroundSpacingM = 1.0;
// Robot positions closer than this to the previous one add nothing to the footprint.
constexpr double kVisitSpacingM = 0.1;
// How far the robot searches for a traversable cell when the map has closed in on it.
constexpr double kEscapeSearchM = 1.5;
constexpr double kEscapeSpeed = 0.2;
// Cells this close to an escape target that the robot could not drive to are not escape targets.
constexpr double kFailedEscapeM = 0.3;
// Commanded at least kBlockedCommand forward but moving slower than kBlockedSpeed for
// kBlockedS: the robot is blocked (MRPT's "apparent collision"); it reverses for kBackOffS.
constexpr double kBlockedCommand = 0.1;
constexpr double kBlockedSpeed = 0.02;
constexpr double kBlockedS = 1.0;
constexpr double kBackOffS = 1.5;
constexpr double kBackOffSpeed = -0.2;
// Within this much path of its goal the robot has arrived: it turns to look rather than creep
// cell by cell along the goal region's edge as the frontier recedes.
constexpr double kArrivedM = 0.4;
// The guard looks this far along the arc, more than the braking distance from top speed.
constexpr double kGuardHorizonM = 2.5;
// Braking leaves this much of the free travel unused. Nearer than about 0.3 m to the body's
// front an obstacle is out of the rig's disparity range (f B / max_disparity is 0.52 m from
// the cameras, which sit 0.2 m behind the front) and often below its view: the robot must not
// close in on what it can no longer measure. This also covers a scan up to a frame old (a person
// walks 0.16 m in 0.2 s) and the command taking effect a cycle late.
constexpr double kStopGapM = 0.3;
// The guard also keeps the points of the scans of the last kScanMemoryS: what has just left the
// view (too near, or below it) still counts for a moment.
constexpr double kScanMemoryS = 1.0;
// When the guard allows less than this speed the robot is held by what the scan shows: those
// points (every one within kHoldingDepthM of the first met along the arc) are remembered as
// obstacles whether the map has them or not, so the next plan goes round them.
constexpr double kHeldSpeed = 0.05;
constexpr double kHoldingDepthM = 0.3;
// Obstacle islands of up to this many cells are specks (NavigationGrid::freeSpecks).
constexpr int kSpeckCells = 2;

double clampAbs(double value, double limit) { return std::max(-limit, std::min(limit, value)); }

SeenFreeMemoryOptions seenFreeOptions(const ExplorerOptions& options) {
  SeenFreeMemoryOptions memory;
  memory.range_m = options.seen_free_range_m;
  memory.field_of_view_deg = options.field_of_view_deg;
  memory.body_radius_m = options.robot_radius_m;
  return memory;
}

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

}  // namespace

const char* phaseName(ExplorerPhase phase) {
  switch (phase) {
    case ExplorerPhase::kLookingAround: return "looking_around";
    case ExplorerPhase::kTurning: return "turning";
    case ExplorerPhase::kDriving: return "driving";
    case ExplorerPhase::kLookingAtFrontier: return "looking_at_frontier";
    case ExplorerPhase::kEscaping: return "escaping";
    case ExplorerPhase::kBackingOff: return "backing_off";
    case ExplorerPhase::kFinished: return "finished";
  }
  return "?";
}

FrontierExplorer::FrontierExplorer(const ExplorerOptions& options)
    : options_(options), near_obstacles_(nearObstacleOptions(options)), seen_free_(seenFreeOptions(options)) {
  planner_options_.body_radius_m = options.robot_radius_m + options.safety_margin_m;
  planner_options_.repulsion_distance_m = options.repulsion_distance_m;
  planner_options_.repulsion_weight = options.repulsion_weight;
  grid_options_.body_radius_m = options.robot_radius_m;
  grid_options_.max_hole_cells = options.max_hole_cells;
  grid_options_.precise_min_disparity = static_cast<float>(options.precise_min_disparity);
  grid_options_.sure_obstacle_g = options.obstacle_memory_min_g;
  status_.phase = options.initial_look_around ? ExplorerPhase::kLookingAround : ExplorerPhase::kTurning;
  turned_rad_ = 0.0;
}

void FrontierExplorer::updateMap(const DisparityTaggedGrid& grid, const mrpt::poses::CPose2D& pose) {
  if (visited_.empty() || std::hypot(pose.x() - visited_.back().x(), pose.y() - visited_.back().y()) >= kVisitSpacingM) {
    visited_.push_back(pose);
  }
  lattice_.anchor(grid.frame());
  target_cells_.clear();
  if (grid_ && target_ && target_label_ >= 0 && target_label_ < static_cast<int>(frontiers_.size())) {
    for (const cv::Point& cell : frontiers_[static_cast<size_t>(target_label_)].cells) {
      target_cells_.insert(worldCell(cell.x, cell.y));
    }
  }
  std::vector<cv::Point2d> obstacles = contacts_;
  for (const mrpt::math::TPoint2D& point : near_obstacles_.points()) obstacles.emplace_back(point.x, point.y);
  seen_free_.update(grid, pose);
  grid_ = std::make_unique<NavigationGrid>(grid, visited_, grid_options_, obstacles, seen_free_.cells());
  if (relaxation_ == Relaxation::kBareBodyPastSpecks) grid_->freeSpecks(kSpeckCells);
  map_frontiers_ = findFrontiers(*grid_, options_.min_frontier_cells);
  awaiting_map_ = false;
  countCloseViews(pose);
  replan();
}

void FrontierExplorer::replan() {
  frontiers_ = map_frontiers_;
  for (Frontier& frontier : frontiers_) {
    frontier.cells.erase(std::remove_if(frontier.cells.begin(), frontier.cells.end(),
                                        [&](const cv::Point& cell) { return isDropped(cell.x, cell.y); }),
                         frontier.cells.end());
  }
  frontiers_.erase(std::remove_if(frontiers_.begin(), frontiers_.end(),
                                  [&](const Frontier& f) {
                                    return static_cast<int>(f.cells.size()) < options_.min_frontier_cells;
                                  }),
                   frontiers_.end());

  CostToGoOptions planner = planner_options_;
  if (relaxation_ != Relaxation::kNone) planner.body_radius_m = options_.robot_radius_m;
  field_ = std::make_unique<CostToGoField>(*grid_, planner);
  const double goal_radius = planner.body_radius_m + options_.goal_distance_m;
  const int reach = static_cast<int>(std::ceil(goal_radius / grid_->resolution()));
  const double reach_sq = goal_radius * goal_radius / (grid_->resolution() * grid_->resolution());
  // Per cell the cheapest seed and its frontier: goals of overlapping frontiers are not repeated.
  cv::Mat1d seed(grid_->height(), grid_->width(), std::numeric_limits<double>::infinity());
  cv::Mat1i label(grid_->height(), grid_->width(), -1);
  const double near_target_sq = (goal_radius + 0.3) * (goal_radius + 0.3);
  for (size_t i = 0; i < frontiers_.size(); ++i) {
    // The target's frontier is the one still near the goal, or still holding some of its cells:
    // a wall resolved look by look keeps the robot working along it, not jumping across the room
    // each time the part nearest the goal is resolved.
    bool is_target = false;
    if (target_) {
      for (const cv::Point& cell : frontiers_[i].cells) {
        const double dx = grid_->centreX(cell.x) - target_->x, dy = grid_->centreY(cell.y) - target_->y;
        if (dx * dx + dy * dy <= near_target_sq || target_cells_.count(worldCell(cell.x, cell.y)) > 0) {
          is_target = true;
          break;
        }
      }
    }
    const bool waits = frontiers_[i].unseen_area_m2 < options_.pocket_area_m2 || !frontiers_[i].borders_unknown;
    const double seed_cost =
        (is_target ? 0.0 : options_.target_switch_penalty_m) + (waits ? options_.pocket_penalty_m : 0.0);
    for (const cv::Point& cell : frontiers_[i].cells) {
      for (int dr = -reach; dr <= reach; ++dr) {
        for (int dc = -reach; dc <= reach; ++dc) {
          const int c = cell.x + dc, r = cell.y + dr;
          if (dc * dc + dr * dr > reach_sq || !grid_->contains(c, r) || !field_->traversable(c, r)) continue;
          if (seed_cost < seed(r, c)) {
            seed(r, c) = seed_cost;
            label(r, c) = static_cast<int>(i);
          }
        }
      }
    }
  }
  std::vector<GoalCell> goals;
  for (int row = 0; row < grid_->height(); ++row) {
    for (int col = 0; col < grid_->width(); ++col) {
      if (label(row, col) >= 0) goals.push_back({col, row, seed(row, col), label(row, col)});
    }
  }
  field_->compute(goals);
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
  readSensedObstacles(robot, mrpt::poses::CPose2D(pose), time_s);
  Command command;
  if (status_.phase == ExplorerPhase::kBackingOff && time_s < back_off_until_) {
    command = backOff(mrpt::poses::CPose2D(pose));
  } else {
    if (status_.phase == ExplorerPhase::kBackingOff) status_.phase = ExplorerPhase::kTurning;
    const Command wanted = decide(mrpt::poses::CPose2D(pose), time_s);
    command = guard(wanted, mrpt::poses::CPose2D(pose));
    const double speed = std::hypot(velocity.vx, velocity.vy);
    if (wanted.speed < kBlockedCommand || speed > kBlockedSpeed) {
      blocked_since_ = -1.0;
    } else if (blocked_since_ < 0.0) {
      blocked_since_ = time_s;
    } else if (time_s - blocked_since_ >= kBlockedS && !finished()) {
      // Held still though it wants to drive: by the guard (what holds it is remembered already),
      // or by something the body touches that no scan shows.
      if (command.speed >= kBlockedCommand) {
        robot.sendApparentCollisionEvent();
        // Whatever stops the body lies on its front arc: remember it as an obstacle there.
        const mrpt::poses::CPose2D at(pose);
        for (const double bearing : {-0.6, -0.3, 0.0, 0.3, 0.6}) {
          const double reach = options_.robot_radius_m + 0.05;
          contacts_.emplace_back(at.x() + reach * std::cos(at.phi() + bearing),
                                 at.y() + reach * std::sin(at.phi() + bearing));
        }
      }
      // An escape the guard will not let the robot drive (what the scans show disagrees with the
      // map) is not tried again from here: the next escape heads for another cell.
      if (status_.phase == ExplorerPhase::kEscaping && escape_to_) failed_escapes_.push_back(*escape_to_);
      status_.phase = ExplorerPhase::kBackingOff;
      back_off_until_ = time_s + kBackOffS;
      blocked_since_ = -1.0;
      command = backOff(mrpt::poses::CPose2D(pose));
    }
  }
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

void FrontierExplorer::readSensedObstacles(mrpt::nav::CRobot2NavInterface& robot, const mrpt::poses::CPose2D& pose,
                                           double time_s) {
  while (!recent_sensed_.empty() && time_s - recent_sensed_.front().first > kScanMemoryS) recent_sensed_.pop_front();
  mrpt::maps::CSimplePointsMap points;
  mrpt::system::TTimeStamp stamp = INVALID_TIMESTAMP;
  if (!robot.senseObstacles(points, stamp) || stamp == last_scan_stamp_) return;
  last_scan_stamp_ = stamp;
  const double reach = kGuardHorizonM + options_.robot_radius_m + options_.guard_margin_m;
  std::vector<mrpt::math::TPoint2D> local, in_map;
  for (size_t i = 0; i < points.size(); ++i) {
    float x = 0.0f, y = 0.0f, z = 0.0f;
    points.getPoint(i, x, y, z);
    local.emplace_back(x, y);
    if (std::hypot(x, y) <= reach) in_map.push_back(composed(pose, local.back()));
  }
  recent_sensed_.emplace_back(time_s, std::move(in_map));
  if (grid_) {
    near_obstacles_.update(local, pose, [&](double x, double y) { return grid_->mapHoldsObstacle(x, y); });
  }
}

FrontierExplorer::Command FrontierExplorer::backOff(const mrpt::poses::CPose2D& pose) {
  // The cameras do not see behind: reversing is allowed only where the map has room for the
  // body all along the way back.
  bool room_behind = true;
  const double back = std::abs(kBackOffSpeed) * kBackOffS;
  for (double along = grid_->resolution(); room_behind && along <= back + 1e-9; along += grid_->resolution()) {
    const double x = pose.x() - along * std::cos(pose.phi()), y = pose.y() - along * std::sin(pose.phi());
    int col = 0, row = 0;
    room_behind = grid_->cellAt(x, y, col, row) && grid_->clearance(col, row) >= options_.robot_radius_m;
  }
  const Command reverse = room_behind ? guard({kBackOffSpeed, 0.0}, pose) : Command{};
  // Hemmed in behind as well: turn on the spot instead (a disc turning touches nothing), which
  // shows the cameras another way out.
  return reverse.speed < 0.0 ? reverse : Command{0.0, options_.look_around_turn_rate};
}

FrontierExplorer::Command FrontierExplorer::guard(Command command, const mrpt::poses::CPose2D& pose) {
  status_.free_travel_m = kGuardHorizonM;
  if (command.speed == 0.0) return command;
  const double reach = kGuardHorizonM + options_.robot_radius_m + options_.guard_margin_m;
  std::vector<mrpt::math::TPoint2D> local;
  const auto add = [&](const mrpt::math::TPoint2D& point) {
    const mrpt::math::TPoint2D robot_frame = pose.inverseComposePoint(point);
    if (std::hypot(robot_frame.x, robot_frame.y) <= reach) local.push_back(robot_frame);
  };
  for (const auto& scan : recent_sensed_) {
    for (const mrpt::math::TPoint2D& point : scan.second) add(point);
  }
  for (const mrpt::math::TPoint2D& point : near_obstacles_.points()) add(point);
  const double radius = options_.robot_radius_m, margin = options_.guard_margin_m;
  const double free = freeTravel(local, radius, margin, command.speed, command.turn_rate, kGuardHorizonM);
  status_.free_travel_m = free;
  const double allowed = std::sqrt(2.0 * options_.braking_deceleration * std::max(0.0, free - kStopGapM));
  if (std::abs(command.speed) <= allowed) return command;
  if (allowed < kHeldSpeed) {
    std::vector<mrpt::math::TPoint2D> holding;
    for (const mrpt::math::TPoint2D& point : local) {
      const double travel = freeTravel({point}, radius, margin, command.speed, command.turn_rate, kGuardHorizonM);
      if (travel <= free + kHoldingDepthM) {
        holding.push_back(composed(pose, point));
      }
    }
    near_obstacles_.remember(holding);
  }
  command.speed = std::copysign(allowed, command.speed);
  return command;
}

cv::Mat3b FrontierExplorer::planImage() const {
  cv::Mat3b image;
  if (!grid_) return image;
  image.create(grid_->height(), grid_->width());
  const auto pixel = [&](int col, int row) -> cv::Vec3b& { return image(grid_->height() - 1 - row, col); };
  for (int row = 0; row < grid_->height(); ++row) {
    for (int col = 0; col < grid_->width(); ++col) {
      switch (grid_->cellClass(col, row)) {
        case NavigationGrid::kFree:
          pixel(col, row) = field_->traversable(col, row) ? cv::Vec3b(200, 255, 200) : cv::Vec3b(255, 255, 255);
          break;
        case NavigationGrid::kUnknown: pixel(col, row) = cv::Vec3b(128, 128, 128); break;
        case NavigationGrid::kImprecise: pixel(col, row) = cv::Vec3b(64, 64, 64); break;
        default: pixel(col, row) = cv::Vec3b(0, 0, 0); break;
      }
    }
  }
  for (const Frontier& frontier : frontiers_) {
    for (const cv::Point& cell : frontier.cells) pixel(cell.x, cell.y) = cv::Vec3b(255, 0, 0);
  }
  const auto mark = [&](double x, double y) {
    int col = 0, row = 0;
    if (grid_->cellAt(x, y, col, row)) pixel(col, row) = cv::Vec3b(0, 0, 255);
  };
  for (const mrpt::math::TPoint2D& point : near_obstacles_.points()) mark(point.x, point.y);
  for (const cv::Point2d& contact : contacts_) mark(contact.x, contact.y);
  return image;
}

FrontierExplorer::Command FrontierExplorer::lookAround(const mrpt::poses::CPose2D& pose) {
  if (status_.phase != ExplorerPhase::kLookingAround) {
    status_.phase = ExplorerPhase::kLookingAround;
    turned_rad_ = 0.0;
  } else {
    turned_rad_ += std::abs(mrpt::math::wrapToPi(pose.phi() - last_phi_));
  }
  last_phi_ = pose.phi();
  if (turned_rad_ >= 2.0 * M_PI) {
    looked_around_here_ = true;
    look_around_x_ = pose.x();
    look_around_y_ = pose.y();
    status_.phase = ExplorerPhase::kTurning;
    return {};
  }
  return {0.0, options_.look_around_turn_rate};
}

FrontierExplorer::Command FrontierExplorer::turnTowards(const mrpt::poses::CPose2D& pose, double x, double y) const {
  const double error = mrpt::math::wrapToPi(std::atan2(y - pose.y(), x - pose.x()) - pose.phi());
  // As fast as the turn can still be braked to a stop at the heading: a proportional law would
  // creep through the last half radian, and the robot turns on the spot a few hundred times an
  // exploration.
  const double turn_rate = std::max(kMinTurnRate, std::min(options_.max_turn_rate, std::sqrt(2.0 * kTurnBraking * std::abs(error))));
  return {0.0, std::copysign(turn_rate, error)};
}

void FrontierExplorer::finish(const std::string& reason) {
  status_.phase = ExplorerPhase::kFinished;
  status_.has_target = false;
  stop_reason_ = reason;
}

bool FrontierExplorer::isDropped(int col, int row) const {
  const double x = grid_->centreX(col), y = grid_->centreY(row);
  const double half_view = options_.field_of_view_deg * M_PI / 360.0;
  for (const mrpt::poses::CPose2D& pose : looked_from_) {
    if (withinView(pose, x, y, options_.looked_at_range_m, half_view)) return true;
  }
  const WorldCell key = worldCell(col, row);
  if (dropped_.count(key) > 0) return true;
  const auto views = close_views_.find(key);
  return views != close_views_.end() && views->second >= kResolvingViews;
}

FrontierExplorer::WorldCell FrontierExplorer::worldCell(int col, int row) const {
  return lattice_.cellAt(grid_->centreX(col), grid_->centreY(row));
}

void FrontierExplorer::countCloseViews(const mrpt::poses::CPose2D& pose) {
  int robot_col = 0, robot_row = 0;
  if (!grid_->cellAt(pose.x(), pose.y(), robot_col, robot_row)) return;
  const double range = options_.looked_at_range_m;
  const double half_view = options_.field_of_view_deg * M_PI / 360.0;
  const auto in_plain_sight = [&](const cv::Point& cell) {
    if (!withinView(pose, grid_->centreX(cell.x), grid_->centreY(cell.y), range, half_view)) return false;
    // Over known free cells only: an obstacle or unseen space between hides the cell.
    return alongStraightLine(cv::Point(robot_col, robot_row), cell, [&](int col, int row) {
      return grid_->cellClass(col, row) == NavigationGrid::kFree;
    });
  };
  for (const Frontier& frontier : map_frontiers_) {
    for (const cv::Point& cell : frontier.cells) {
      if (in_plain_sight(cell)) ++close_views_[worldCell(cell.x, cell.y)];
    }
  }
}

void FrontierExplorer::dropFrontier(size_t index, const mrpt::poses::CPose2D& pose, bool whole) {
  looked_from_.push_back(pose);
  if (whole) {
    for (const cv::Point& cell : frontiers_[index].cells) dropped_.insert(worldCell(cell.x, cell.y));
  }
  target_.reset();
  target_label_ = -1;
  target_cells_.clear();
  relaxation_ = Relaxation::kNone;
  replan();
}

FrontierExplorer::Command FrontierExplorer::decide(const mrpt::poses::CPose2D& pose, double time_s) {
  if (!grid_ || awaiting_map_) return {};
  if (looked_around_here_ && std::hypot(pose.x() - look_around_x_, pose.y() - look_around_y_) > kLookAroundSpacingM) {
    looked_around_here_ = false;
  }
  if (forgot_here_ && std::hypot(pose.x() - forgot_x_, pose.y() - forgot_y_) > kLookAroundSpacingM) {
    forgot_here_ = false;
  }
  if (status_.phase == ExplorerPhase::kLookingAround) {
    const Command turn = lookAround(pose);
    if (status_.phase == ExplorerPhase::kLookingAround) return turn;
  }
  int col = 0, row = 0;
  if (!grid_->cellAt(pose.x(), pose.y(), col, row)) {
    finish("the robot is outside its own map");
    return {};
  }

  if (!field_->traversable(col, row)) {
    // The map has closed in (a moving obstacle came close, or a better view put a wall nearer):
    // move to the nearest cell where the body fits, over free cells only.
    if (!escape_to_ || status_.phase != ExplorerPhase::kEscaping) {
      escape_to_.reset();
      const int reach = static_cast<int>(std::ceil(kEscapeSearchM / grid_->resolution()));
      std::deque<cv::Point> queue{cv::Point(col, row)};
      cv::Mat1b seen(grid_->height(), grid_->width(), uint8_t{0});
      seen(row, col) = 1;
      while (!queue.empty() && !escape_to_) {
        const cv::Point cell = queue.front();
        queue.pop_front();
        static const int kSteps[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
        for (const auto& step : kSteps) {
          const int c = cell.x + step[0], r = cell.y + step[1];
          if (!grid_->contains(c, r) || seen(r, c) || std::abs(c - col) > reach || std::abs(r - row) > reach) continue;
          seen(r, c) = 1;
          if (grid_->cellClass(c, r) != NavigationGrid::kFree) continue;
          const cv::Point2d centre(grid_->centreX(c), grid_->centreY(r));
          const bool failed_before =
              std::any_of(failed_escapes_.begin(), failed_escapes_.end(), [&](const cv::Point2d& failed) {
                return std::hypot(failed.x - centre.x, failed.y - centre.y) < kFailedEscapeM;
              });
          if (field_->traversable(c, r) && !failed_before) {
            escape_to_ = centre;
            break;
          }
          queue.emplace_back(c, r);
        }
      }
      if (!escape_to_) {
        failed_escapes_.clear();
        if (!looked_around_here_) return lookAround(pose);
        finish("boxed in: no cell within " + std::to_string(kEscapeSearchM).substr(0, 3) +
               " m where the robot's body fits in known free space");
        return {};
      }
      status_.phase = ExplorerPhase::kEscaping;
    }
    const Command turn = turnTowards(pose, escape_to_->x, escape_to_->y);
    const double error = mrpt::math::wrapToPi(std::atan2(escape_to_->y - pose.y(), escape_to_->x - pose.x()) - pose.phi());
    if (std::abs(error) > kFacedRad * 2.0) return turn;
    return {kEscapeSpeed, clampAbs(options_.heading_gain * error, options_.max_turn_rate)};
  }
  if (status_.phase == ExplorerPhase::kEscaping) status_.phase = ExplorerPhase::kTurning;
  escape_to_.reset();
  failed_escapes_.clear();

  if (!field_->reachable(col, row)) {
    if (!looked_around_here_) return lookAround(pose);
    if (frontiers_.empty() && looked_from_.empty()) {
      finish("no frontier left: every known free cell borders only known cells");
    } else if (frontiers_.empty()) {
      finish("no frontier left: the rest were looked at from up close without resolving (" +
             std::to_string(looked_from_.size()) + " looks)");
    } else if (!forgot_here_ &&
               near_obstacles_.forgetUnconfirmed([&](double x, double y) { return grid_->mapHoldsObstacle(x, y); }) > 0) {
      // What closed the way may have been the robot's own memory of near obstacles: a person seen
      // in the same place too often to have been seen gone. Only what the map still holds is kept
      // now; plan again on the next map.
      forgot_here_ = true;
      forgot_x_ = pose.x();
      forgot_y_ = pose.y();
      awaiting_map_ = true;
    } else if (relaxation_ == Relaxation::kNone && options_.safety_margin_m > 0.0) {
      // Doors seen obliquely come out narrower than they are (their jambs' regions of
      // uncertainty, paper section 3.2): try the gaps the bare body fits through; the guard
      // still keeps it off what the scans show. Until the next frontier is reached.
      relaxation_ = Relaxation::kBareBody;
      replan();
    } else if (relaxation_ != Relaxation::kBareBodyPastSpecks) {
      // Boxed in by specks: lone obstacle cells amid free space, each inflated by the body's
      // radius, in the gaps beside furniture. Up close they are below the cameras' view, so no
      // look clears them; most are stereo mismatches that repeated. Plan past
      // them; the guard brakes for any the scans show to be real.
      relaxation_ = Relaxation::kBareBodyPastSpecks;
      grid_->freeSpecks(kSpeckCells);
      near_obstacles_.forgetUnconfirmed([&](double x, double y) {
        int c = 0, r = 0;
        return !grid_->cellAt(x, y, c, r) || grid_->cellClass(c, r) != NavigationGrid::kFree;
      });
      map_frontiers_ = findFrontiers(*grid_, options_.min_frontier_cells);
      replan();
    } else {
      size_t cells = 0;
      for (const Frontier& frontier : frontiers_) cells += frontier.cells.size();
      finish("no reachable frontier left: " + std::to_string(frontiers_.size()) + " frontier(s) of " +
             std::to_string(cells) + " cells lie beyond gaps narrower than the robot or across unknown space");
    }
    return {};
  }

  const std::vector<cv::Point> path = field_->pathFrom(col, row);
  const cv::Point goal = path.back();
  const cv::Point2d goal_point(grid_->centreX(goal.x), grid_->centreY(goal.y));
  if (!target_ || std::hypot(goal_point.x - target_->x, goal_point.y - target_->y) > 1.0) {
    best_cost_ = field_->cost(col, row);
    best_cost_time_ = time_s;
  }
  target_ = goal_point;
  target_label_ = field_->label(col, row);
  status_.has_target = true;
  status_.target_x = goal_point.x;
  status_.target_y = goal_point.y;
  status_.cost_to_go = field_->cost(col, row);

  if (field_->cost(col, row) - field_->cost(goal.x, goal.y) <= kArrivedM) {
    // Arrived: face the nearest cell of the frontier, hold for the map to catch up, and if the
    // frontier is still there (unknown behind something stereo cannot resolve), drop it.
    const Frontier& frontier = frontiers_[static_cast<size_t>(field_->label(col, row))];
    cv::Point nearest_cell;
    double nearest_sq = std::numeric_limits<double>::infinity();
    for (const cv::Point& cell : frontier.cells) {
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
    const double error = mrpt::math::wrapToPi(std::atan2(nearest.y - pose.y(), nearest.x - pose.x()) - pose.phi());
    if (std::abs(error) > kFacedRad && nearest_sq > 1e-6) return turnTowards(pose, nearest.x, nearest.y);
    phase_start_time_ = std::min(phase_start_time_, time_s);
    if (time_s - phase_start_time_ >= kLookHoldS) {
      // The faced cell goes in any case, so that every look makes progress.
      dropped_.insert(worldCell(nearest_cell.x, nearest_cell.y));
      dropFrontier(static_cast<size_t>(field_->label(col, row)), pose, nearest_sq < 1e-6);
      status_.phase = ExplorerPhase::kTurning;
    }
    return {};
  }
  if (status_.phase == ExplorerPhase::kLookingAtFrontier) status_.phase = ExplorerPhase::kTurning;

  if (status_.cost_to_go < best_cost_ - kProgressM) {
    best_cost_ = status_.cost_to_go;
    best_cost_time_ = time_s;
  } else if (time_s - best_cost_time_ > options_.stuck_timeout_s) {
    dropFrontier(static_cast<size_t>(field_->label(col, row)), pose, true);
    best_cost_time_ = time_s;
    return {};
  }
  return drive(pose, path);
}

FrontierExplorer::Command FrontierExplorer::drive(const mrpt::poses::CPose2D& pose, const std::vector<cv::Point>& path) {
  // Carrot: the first path cell at least lookahead_m along the path; and the whole path length,
  // to brake in time for its end (the edge of the known map).
  double along = 0.0, remaining = 0.0;
  cv::Point2d carrot(grid_->centreX(path.back().x), grid_->centreY(path.back().y));
  bool carrot_set = false;
  for (size_t i = 1; i < path.size(); ++i) {
    const double step = std::hypot(path[i].x - path[i - 1].x, path[i].y - path[i - 1].y) * grid_->resolution();
    remaining += step;
    along += step;
    if (!carrot_set && along >= options_.lookahead_m) {
      carrot = cv::Point2d(grid_->centreX(path[i].x), grid_->centreY(path[i].y));
      carrot_set = true;
    }
  }
  const double error = mrpt::math::wrapToPi(std::atan2(carrot.y - pose.y(), carrot.x - pose.x()) - pose.phi());
  if (status_.phase != ExplorerPhase::kDriving && std::abs(error) > kFacedRad) return turnTowards(pose, carrot.x, carrot.y);
  if (std::abs(error) > options_.turn_in_place_rad) {
    status_.phase = ExplorerPhase::kTurning;
    return turnTowards(pose, carrot.x, carrot.y);
  }
  status_.phase = ExplorerPhase::kDriving;
  int col = 0, row = 0;
  grid_->cellAt(pose.x(), pose.y(), col, row);
  const double room = grid_->obstacleDistance(col, row) - planner_options_.body_radius_m;
  const double room_factor = std::max(0.3, std::min(1.0, room / (options_.repulsion_distance_m + 1e-9)));
  // Slower with the square of the heading error: the carrot on a grid path swings 5-15 degrees
  // from cell to cell, which in proportion cost a third of the speed (top speed 1.27-1.48 m/s
  // over the office seeds); at the turn-in-place angle it is 0.3 of full speed as before.
  const double heading_share = error / options_.turn_in_place_rad;
  double speed = options_.max_speed_mps * room_factor * (1.0 - 0.7 * heading_share * heading_share);
  speed = std::min(speed, std::sqrt(2.0 * options_.braking_deceleration * remaining));
  return {speed, clampAbs(options_.heading_gain * error, options_.max_turn_rate)};
}

}  // namespace stereonav
