#pragma once

#include <cmath>

#include "common/ini_section.h"

namespace stereonav {

// How the explorer plans and drives (paper section 5: a mixture of shortest path and potential
// field methods). Distances in metres, angles in degrees in the ini, radians here.
struct ExplorerOptions {
  // The body is a disc of this radius; obstacles AND unknown cells are inflated by it plus the
  // margin, so the body never overlaps a cell that is not known free.
  double robot_radius_m = 0.3;
  double safety_margin_m = 0.1;
  // Potential field: within this distance of the inflated obstacles a cell's step cost grows up
  // to (1 + repulsion_weight) times its length, so paths keep to the middle of free space.
  double repulsion_distance_m = 0.6;
  double repulsion_weight = 4.0;
  // Unknown islands of at most this many cells amid free cells hold mixed evidence, not unseen
  // space: they count as free (NavigationGrid).
  int max_hole_cells = 4;
  // Obstacles known only from readings below this disparity are worth a closer look
  // (NavigationGridOptions::precise_min_disparity). 0: none.
  double precise_min_disparity = 3.0;
  // Goals are the traversable cells within this distance of a frontier cell.
  double goal_distance_m = 0.2;
  // Frontier clusters of fewer cells are stereo noise, not openings.
  int min_frontier_cells = 3;
  // Cost (metres of path) added to every frontier but the current target, so that the robot
  // does not dither between two frontiers at similar distances.
  double target_switch_penalty_m = 2.0;
  // Cost (metres of path) added to frontiers that border only a pocket of unresolved cells
  // smaller than pocket_area_m2 (under a desk, behind a cabinet, a ghost band in a room already
  // seen), or only obstacles seen from far (where a wall is, not new floor): the rest of the
  // building comes first, and these are looked into when nearby or when nothing else is left.
  double pocket_area_m2 = 3.0;
  double pocket_penalty_m = 25.0;
  // When the robot has reached a frontier and faced it, the frontier cells still left within
  // this range and inside the field of view are dropped: looking again from there would not
  // resolve them (unknown behind something stereo cannot see, e.g. a textureless wall). So are
  // frontier cells that were in plain sight within this range for as long as a look lasts.
  double looked_at_range_m = 1.0;
  double field_of_view_deg = 90.0;  // of the reference camera (paper section 2.1)
  // Floor seen free within this range stays free for the planner where far readings later smear
  // it (seen_free_memory.h). 0: off.
  double seen_free_range_m = 2.0;
  // Reactive control.
  double max_speed_mps = 1.5;
  double max_turn_rate = 1.2;  // rad/s
  double braking_deceleration = 0.8;  // m/s^2 planned, below the robot's limit
  double heading_gain = 2.0;
  // With the 90 degree field of view of the rig the robot turns on the spot until the path ahead
  // is within this angle of its heading, so it has looked where it is going before driving.
  double turn_in_place_rad = 25.0 * M_PI / 180.0;
  double lookahead_m = 0.3;
  // A full turn on the spot at the start, so the first plan sees all around, at a rate slow
  // enough for every direction to stay in view for the several frames its cells need to turn
  // free (the grid's update rule needs a few CLEAR updates, paper section 3.4).
  bool initial_look_around = true;
  double look_around_turn_rate = 1.0;  // rad/s
  // No progress towards any goal for this long: the target is dropped as unreachable.
  double stuck_timeout_s = 15.0;
  // The reactive guard (free_travel.h): the robot brakes so that its body, widened by this
  // margin, stops short of the obstacles of the newest stereo scans (CRobot2NavInterface::
  // senseObstacles) and of the remembered near obstacles along the commanded arc, whatever the
  // map says.
  double guard_margin_m = 0.1;
  // Obstacle points the scans show within obstacle_memory_range_m are obstacles for the planner
  // and the guard until a later scan sees past them from at least obstacle_memory_blind_m away
  // (near_obstacle_memory.h): far views see under chair seats and table tops (paper section 6.1).
  double obstacle_memory_range_m = 2.0;
  double obstacle_memory_blind_m = 1.0;
  // Only points where the map's occupancy value is at least this are kept: several readings
  // agree there (a stereo mismatch seldom repeats).
  int obstacle_memory_min_g = 200;
};

// Section [explorer]: robot_radius_m, safety_margin_m, repulsion_distance_m, repulsion_weight,
// max_hole_cells, precise_min_disparity, goal_distance_m, min_frontier_cells, target_switch_penalty_m, pocket_area_m2,
// pocket_penalty_m, looked_at_range_m, field_of_view_deg,
// seen_free_range_m,
// max_speed_mps, max_turn_rate, braking_deceleration, heading_gain, turn_in_place_deg,
// lookahead_m, initial_look_around, look_around_turn_rate, stuck_timeout_s, guard_margin_m,
// obstacle_memory_range_m, obstacle_memory_blind_m, obstacle_memory_min_g.
ExplorerOptions loadExplorerOptions(IniSection& section);

}  // namespace stereonav
