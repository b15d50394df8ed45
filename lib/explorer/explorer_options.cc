#include "explorer/explorer_options.h"

#include <cmath>

namespace stereonav {

ExplorerOptions loadExplorerOptions(IniSection& section) {
  ExplorerOptions options;
  const auto positive = [&](const std::string& key, double value) {
    const double read = section.getDouble(key, value);
    if (!(read > 0.0)) throw ConfigError("[" + section.name() + "] " + key + ": must be positive");
    return read;
  };
  const auto non_negative = [&](const std::string& key, double value) {
    const double read = section.getDouble(key, value);
    if (!(read >= 0.0)) throw ConfigError("[" + section.name() + "] " + key + ": must not be negative");
    return read;
  };
  options.robot_radius_m = positive("robot_radius_m", options.robot_radius_m);
  options.safety_margin_m = non_negative("safety_margin_m", options.safety_margin_m);
  options.repulsion_distance_m = non_negative("repulsion_distance_m", options.repulsion_distance_m);
  options.repulsion_weight = non_negative("repulsion_weight", options.repulsion_weight);
  options.max_hole_cells = section.getInt("max_hole_cells", options.max_hole_cells);
  if (options.max_hole_cells < 0) throw ConfigError("[" + section.name() + "] max_hole_cells: must not be negative");
  options.precise_min_disparity = non_negative("precise_min_disparity", options.precise_min_disparity);
  options.goal_distance_m = positive("goal_distance_m", options.goal_distance_m);
  options.min_frontier_cells = section.getInt("min_frontier_cells", options.min_frontier_cells);
  if (options.min_frontier_cells < 1) {
    throw ConfigError("[" + section.name() + "] min_frontier_cells: must be at least 1");
  }
  options.target_switch_penalty_m = non_negative("target_switch_penalty_m", options.target_switch_penalty_m);
  options.looked_at_range_m = positive("looked_at_range_m", options.looked_at_range_m);
  options.field_of_view_deg = positive("field_of_view_deg", options.field_of_view_deg);
  if (options.field_of_view_deg >= 180.0) {
    throw ConfigError("[" + section.name() + "] field_of_view_deg: must be below 180");
  }
  options.max_speed_mps = positive("max_speed_mps", options.max_speed_mps);
  options.max_turn_rate = positive("max_turn_rate", options.max_turn_rate);
  options.braking_deceleration = positive("braking_deceleration", options.braking_deceleration);
  options.heading_gain = positive("heading_gain", options.heading_gain);
  const double turn_in_place_deg = positive("turn_in_place_deg", options.turn_in_place_rad * 180.0 / M_PI);
  if (turn_in_place_deg > 90.0) {
    throw ConfigError("[" + section.name() + "] turn_in_place_deg: must be at most 90");
  }
  options.turn_in_place_rad = turn_in_place_deg * M_PI / 180.0;
  options.lookahead_m = positive("lookahead_m", options.lookahead_m);
  options.initial_look_around = section.getBool("initial_look_around", options.initial_look_around);
  options.look_around_turn_rate = positive("look_around_turn_rate", options.look_around_turn_rate);
  options.stuck_timeout_s = positive("stuck_timeout_s", options.stuck_timeout_s);
  return options;
}

}  // namespace stereonav
