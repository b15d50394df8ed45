#pragma once

#include "common/ini_section.h"

namespace stereonav {

// How the explorer plans and drives (paper section 5: a mixture of shortest path and potential
// field methods). Distances in metres, angles in degrees in the ini, radians here.
struct ExplorerOptions {
  // The body is a disc of this radius; obstacles AND unknown cells are inflated by it plus the
  // margin, so the body never overlaps a cell that is not known free.
  double robot_radius_m = 0.3;
  double safety_margin_m = 0.05;
  // Potential field: within this distance of the inflated obstacles a cell's step cost grows up
  // to (1 + repulsion_weight) times its length, so paths keep to the middle of free space.
  double repulsion_distance_m = 0.6;
  double repulsion_weight = 4.0;
  // Goals are the traversable cells within this distance of a frontier cell.
  double goal_distance_m = 0.5;
  // Frontier clusters of fewer cells are stereo noise, not openings.
  int min_frontier_cells = 3;
  // Cost (metres of path) added to every frontier but the current target, so that the robot
  // does not dither between two frontiers at similar distances.
  double target_switch_penalty_m = 2.0;
  // A frontier the robot has reached and looked at without it disappearing (unknown behind
  // something stereo cannot see) is dropped within this radius of where it looked at it.
  double exhausted_frontier_radius_m = 0.6;
  // Reactive control.
  double max_speed_mps = 1.5;
  double max_turn_rate = 1.2;  // rad/s
  double braking_deceleration = 0.8;  // m/s^2 planned, below the robot's limit
  double heading_gain = 2.0;
  // With the 90 degree field of view of the rig the robot turns on the spot until the path ahead
  // is within this angle of its heading, so it has looked where it is going before driving.
  double turn_in_place_rad = 0.6;
  double lookahead_m = 0.6;
  // A full turn on the spot at the start, so the first plan sees all around.
  bool initial_look_around = true;
  // No progress towards any goal for this long: the target is dropped as unreachable.
  double stuck_timeout_s = 15.0;
};

// Section [explorer]: robot_radius_m, safety_margin_m, repulsion_distance_m, repulsion_weight,
// goal_distance_m, min_frontier_cells, target_switch_penalty_m, exhausted_frontier_radius_m,
// max_speed_mps, max_turn_rate, braking_deceleration, heading_gain, turn_in_place_deg,
// lookahead_m, initial_look_around, stuck_timeout_s.
ExplorerOptions loadExplorerOptions(IniSection& section);

}  // namespace stereonav
