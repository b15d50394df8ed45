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
  // What the body would pass clear of but within the margin (a door jamb) slows the robot to this
  // speed instead of holding it: a door 0.8 m wide leaves a body 0.6 m wide 0.1 m each side.
  double pass_beside_speed_mps = 0.15;
  // Obstacle points the scans show within obstacle_memory_range_m are obstacles for the planner
  // and the guard until a later scan sees past them from at least obstacle_memory_blind_m away
  // (near_obstacle_memory.h): far views see under chair seats and table tops (paper section 6.1).
  double obstacle_memory_range_m = 2.0;
  double obstacle_memory_blind_m = 1.0;
  // Only points where the map's occupancy value is at least this are kept: several readings
  // agree there (a stereo mismatch seldom repeats).
  int obstacle_memory_min_g = 200;

  // The safety guard (safety_guard.h). It looks this far along the commanded arc, more than the
  // braking distance from top speed.
  double guard_horizon_m = 2.5;
  // Braking leaves this much of the free travel unused. Nearer than about 0.3 m to the body's
  // front an obstacle is out of the rig's disparity range (f B / max_disparity is 0.52 m from
  // the cameras, which sit 0.2 m behind the front) and often below its view: the robot must not
  // close in on what it can no longer measure. This also covers a scan up to a frame old (a person
  // walks 0.16 m in 0.2 s) and the command taking effect a cycle late.
  double stop_gap_m = 0.3;
  // The points of the scans of the last scan_memory_s count too: what has just left the view
  // (too near, or below it) still counts for a moment.
  double scan_memory_s = 1.0;
  // When the guard allows less than held_speed_mps the robot is held by what the scan shows: those
  // points (every one within holding_depth_m of the first met along the arc) are remembered as
  // obstacles whether the map has them or not, so the next plan goes round them.
  double held_speed_mps = 0.05;
  double holding_depth_m = 0.3;
  // Commanded at least blocked_command_mps forward but moving slower than blocked_speed_mps for
  // blocked_s: the robot is blocked (MRPT's "apparent collision"); it reverses at back_off_speed_mps
  // for back_off_s.
  double blocked_command_mps = 0.1;
  double blocked_speed_mps = 0.02;
  double blocked_s = 1.0;
  double back_off_speed_mps = 0.2;
  double back_off_s = 1.5;

  // The motion controller (motion_controller.h). Facing counts as done within facing_tolerance_rad
  // of heading error; turning on the spot never goes slower than min_turn_rate (rad/s), so it
  // ends, and plans to brake at turn_braking (rad/s^2), within what robots like the paper's
  // manage (the simulated one: 4).
  double facing_tolerance_rad = 0.2;
  double min_turn_rate = 0.25;
  double turn_braking = 3.0;
  // A robot that has moved this far from its last look-around may look around again.
  double look_around_spacing_m = 1.0;
  // Driving to the nearest cell where the body fits when the map has closed in on the robot.
  double escape_speed_mps = 0.2;

  // The frontier memory (frontier_memory.h). A frontier cell in plain sight within
  // looked_at_range_m for this many maps without being resolved is dropped: without this the
  // edges of what stereo cannot resolve (under a table top, a wall eroded by grazing rays and
  // rebuilt by far readings) flicker back as new frontier cells, and the robot tours a finished
  // room. Twelve views match look_hold_s at 5 Hz.
  int resolving_views = 12;

  // The phase machine (frontier_explorer.h). After facing a frontier the robot holds still this
  // long so that the map sees what is behind it before the frontier is judged: taking a cell that
  // far readings saturated (255) below the free threshold (50) takes eleven CLEAR updates of
  // K = 20 (paper section 3.4), twelve frames at 5 Hz. A frontier that resolves sooner ends the
  // look at once (the next plan has another target).
  double look_hold_s = 2.4;
  // Within this much cost-to-go of its goal the robot has arrived: it turns to look rather than
  // creep cell by cell along the goal region's edge as the frontier recedes. The cost is path
  // plus the potential field's repulsion, so beside a wall it is reached only nearer the goal.
  double arrived_m = 0.4;
  // Progress: the cost-to-go must drop by progress_m within stuck_timeout_s.
  double progress_m = 0.3;
  // Robot positions closer than this to the previous one add nothing to the footprint.
  double visit_spacing_m = 0.1;
  // How far the robot searches for a cell where its body fits when the map has closed in on it;
  // cells within failed_escape_m of an escape target it could not drive to are not tried again.
  double escape_search_m = 1.5;
  double failed_escape_m = 0.3;
  // Obstacle islands of up to this many cells are specks (NavigationGrid::freeSpecks), planned
  // past when nothing else is reachable.
  int speck_cells = 2;
  // When no frontier is reachable, not even by the bare body past specks, each is looked at
  // from the nearest place the body reaches within this distance of it, one frontier at a
  // time, before the robot gives up: a closer view often opens what far readings closed (a
  // door's jambs a cell too wide, streaks of unseen floor between far readings' columns). A
  // frontier still there after that look is given up. 0: give up at once.
  double look_from_afar_m = 2.0;
  // Before giving up on every frontier the robot starts the recovery again: it looks around
  // afresh and plans without relaxing. While it climbed, the map changed (a person who boxed it
  // in has left, a speck the guard held it at is kept from then on), and what it gave up may be
  // reachable now. At most recovery_restarts times a run, recovery_restart_spacing_s apart, so
  // that a building that is truly finished ends the run. 0: give up at once.
  int recovery_restarts = 3;
  double recovery_restart_spacing_s = 30.0;
};

// Section [explorer]: robot_radius_m, safety_margin_m, repulsion_distance_m, repulsion_weight,
// max_hole_cells, precise_min_disparity, goal_distance_m, min_frontier_cells, target_switch_penalty_m, pocket_area_m2,
// pocket_penalty_m, looked_at_range_m, field_of_view_deg,
// seen_free_range_m,
// max_speed_mps, max_turn_rate, braking_deceleration, heading_gain, turn_in_place_deg,
// lookahead_m, initial_look_around, look_around_turn_rate, stuck_timeout_s, guard_margin_m,
// pass_beside_speed_mps,
// obstacle_memory_range_m, obstacle_memory_blind_m, obstacle_memory_min_g,
// guard_horizon_m, stop_gap_m, scan_memory_s, held_speed_mps, holding_depth_m,
// blocked_command_mps, blocked_speed_mps, blocked_s, back_off_speed_mps, back_off_s,
// facing_tolerance_deg, min_turn_rate, turn_braking, look_around_spacing_m, escape_speed_mps,
// resolving_views, look_hold_s, arrived_m, progress_m, visit_spacing_m, escape_search_m,
// failed_escape_m, speck_cells, look_from_afar_m, recovery_restarts, recovery_restart_spacing_s.
ExplorerOptions loadExplorerOptions(IniSection& section);

}  // namespace stereonav
