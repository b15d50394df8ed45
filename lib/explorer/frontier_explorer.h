#pragma once

#include <mrpt/nav/reactive/CRobot2NavInterface.h>
#include <mrpt/poses/CPose2D.h>

#include <deque>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <utility>
#include <string>
#include <vector>

#include "explorer/cost_to_go_field.h"
#include "explorer/explorer_options.h"
#include "explorer/frontier_finder.h"
#include "explorer/navigation_grid.h"
#include "explorer/near_obstacle_memory.h"
#include "explorer/seen_free_memory.h"
#include "explorer/world_cell_lattice.h"

namespace stereonav {

enum class ExplorerPhase {
  kLookingAround,      // a full turn on the spot (at the start, and before giving up)
  kTurning,            // facing the path before driving it (90 degree field of view)
  kDriving,            // following the cost-to-go towards the target frontier
  kLookingAtFrontier,  // arrived: facing the frontier so the cameras see past it
  kEscaping,           // the map closed in around the robot: back to the nearest traversable cell
  kBackingOff,         // told to drive but not moving (in contact with something unmapped): reverse
  kFinished,
};

const char* phaseName(ExplorerPhase phase);

// What the explorer is doing, for the navigation trace.
struct ExplorerStatus {
  ExplorerPhase phase = ExplorerPhase::kLookingAround;
  size_t frontiers = 0;            // frontier clusters in the newest map
  bool has_target = false;
  double target_x = 0.0;           // end of the current path (map frame)
  double target_y = 0.0;
  double cost_to_go = 0.0;         // metres-equivalent of path left (0 without target)
  double speed_command = 0.0;
  double turn_rate_command = 0.0;
  // How far the body could go along the command's arc before touching what the newest stereo
  // scans show (free_travel.h); the guard's look-ahead when nothing is in the way.
  double free_travel_m = 0.0;
};

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
// Under the planner a reactive guard reads the robot's sensed obstacles every cycle
// (senseObstacles: the newest stereo scan) and brakes so that the body stops short of them and
// of the obstacles seen up close earlier (near_obstacle_memory.h), which the planner avoids too.
class FrontierExplorer {
 public:
  explicit FrontierExplorer(const ExplorerOptions& options);

  // The newest map, built in the robot's pose frame, and the pose it was last updated at.
  void updateMap(const DisparityTaggedGrid& grid, const mrpt::poses::CPose2D& pose);

  // One control cycle: reads the robot and commands it. False once exploration has finished
  // (the robot has been told to stop); stopReason() says why.
  bool controlStep(mrpt::nav::CRobot2NavInterface& robot);

  bool finished() const { return status_.phase == ExplorerPhase::kFinished; }
  const std::string& stopReason() const { return stop_reason_; }
  const ExplorerStatus& status() const { return status_; }

  // The newest plan as the explorer sees it, one pixel per cell, top row = max y: obstacles black
  // (imprecise ones dark grey), unknown grey, free white, cells where the body fits light green,
  // frontier cells blue, remembered near obstacles and contacts red. Empty before the first map.
  cv::Mat3b planImage() const;

 private:
  struct Command {
    double speed = 0.0;
    double turn_rate = 0.0;
  };

  void replan();
  Command decide(const mrpt::poses::CPose2D& pose, double time_s);
  Command drive(const mrpt::poses::CPose2D& pose, const std::vector<cv::Point>& path);
  Command turnTowards(const mrpt::poses::CPose2D& pose, double x, double y) const;
  Command lookAround(const mrpt::poses::CPose2D& pose);
  // Reads a new scan, if there is one, into recent_sensed_ and near_obstacles_.
  void readSensedObstacles(mrpt::nav::CRobot2NavInterface& robot, const mrpt::poses::CPose2D& pose, double time_s);
  // `command` slowed so that the body can stop short of the sensed and remembered obstacles
  // (free_travel.h).
  Command guard(Command command, const mrpt::poses::CPose2D& pose);
  // Reversing out of a blocked spot, guarded; turning on the spot if that is blocked too.
  Command backOff(const mrpt::poses::CPose2D& pose);
  void finish(const std::string& reason);
  // Cells the robot at `pose` has in view within looked_at_range_m are never frontier again:
  // looking from there did not resolve them, and as the map changes the frontier may move by a
  // cell or two without becoming any more resolvable. `whole`: also every current cell of
  // frontier `index` (given up as unreachable).
  void dropFrontier(size_t index, const mrpt::poses::CPose2D& pose, bool whole);
  bool isDropped(int col, int row) const;
  // A cell's name from map to map (world_cell_lattice.h).
  using WorldCell = WorldCellLattice::Cell;
  WorldCell worldCell(int col, int row) const;
  // Every new map is a new view: the frontier cells the robot at `pose` has in plain sight within
  // looked_at_range_m count one more view (see kResolvingViews).
  void countCloseViews(const mrpt::poses::CPose2D& pose);

  ExplorerOptions options_;
  CostToGoOptions planner_options_;
  NavigationGridOptions grid_options_;
  std::vector<mrpt::poses::CPose2D> visited_;
  std::vector<cv::Point2d> contacts_;  // where the body met something unmapped
  // Obstacle points of the scans of the last kScanMemoryS within the guard's reach (map frame),
  // by the time they were read.
  std::deque<std::pair<double, std::vector<mrpt::math::TPoint2D>>> recent_sensed_;
  mrpt::system::TTimeStamp last_scan_stamp_ = INVALID_TIMESTAMP;
  NearObstacleMemory near_obstacles_;
  SeenFreeMemory seen_free_;
  std::unique_ptr<NavigationGrid> grid_;
  WorldCellLattice lattice_;
  std::unique_ptr<CostToGoField> field_;
  // The newest map's frontiers as found, and as planned for (without the dropped cells).
  std::vector<Frontier> map_frontiers_;
  std::vector<Frontier> frontiers_;
  // Views that did not resolve their frontier: the robot's pose when it looked.
  std::vector<mrpt::poses::CPose2D> looked_from_;
  // Frontier cells given up whole.
  std::set<WorldCell> dropped_;
  // Frontier cells: the maps in which they were in plain sight up close.
  std::map<WorldCell, int> close_views_;
  std::optional<cv::Point2d> target_;
  // The frontier the path leads to (index into frontiers_), and its cells as the previous map
  // had them: a frontier sharing a cell with it is still the target.
  int target_label_ = -1;
  std::set<WorldCell> target_cells_;
  // A look-around: the heading turned so far and the heading at the last cycle.
  double turned_rad_ = 0.0;
  double last_phi_ = 0.0;
  bool looked_around_here_ = false;
  // The memory of near obstacles was pruned to what the map holds (no frontier was reachable),
  // here, and the next map has not come yet.
  bool forgot_here_ = false;
  double forgot_x_ = 0.0;
  double forgot_y_ = 0.0;
  bool awaiting_map_ = false;
  // How far planning is relaxed, until the next frontier is reached: no frontier was reachable
  // with the safety margin, or then with the bare body either.
  enum class Relaxation { kNone, kBareBody, kBareBodyPastSpecks };
  Relaxation relaxation_ = Relaxation::kNone;
  double look_around_x_ = 0.0;  // where the last full look-around was
  double look_around_y_ = 0.0;
  // Progress watch: the lowest cost-to-go reached and when.
  double best_cost_ = 0.0;
  double best_cost_time_ = 0.0;
  double phase_start_time_ = 0.0;
  std::optional<cv::Point2d> escape_to_;
  // Escape targets the robot was blocked on the way to, since it last stood where its body fits.
  std::vector<cv::Point2d> failed_escapes_;
  // Blocked watch: since when the robot has been told to move forward without moving, and when
  // the current back-off ends.
  double blocked_since_ = -1.0;
  double back_off_until_ = 0.0;
  ExplorerStatus status_;
  std::string stop_reason_;
};

}  // namespace stereonav
