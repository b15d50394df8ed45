#include "explorer/explorer_options.h"

#include <cmath>

namespace stereonav {
namespace {

// The tunables of the safety guard, the motion controller, the frontier memory and the phase machine.
void readPartTunables(IniSection& section, ExplorerOptions& options) {
  options.guard_horizon_m = section.getPositive("guard_horizon_m", options.guard_horizon_m);
  options.stop_gap_m = section.getNonNegative("stop_gap_m", options.stop_gap_m);
  options.scan_memory_s = section.getNonNegative("scan_memory_s", options.scan_memory_s);
  options.held_speed_mps = section.getNonNegative("held_speed_mps", options.held_speed_mps);
  options.holding_depth_m = section.getNonNegative("holding_depth_m", options.holding_depth_m);
  options.blocked_command_mps = section.getPositive("blocked_command_mps", options.blocked_command_mps);
  options.blocked_speed_mps = section.getNonNegative("blocked_speed_mps", options.blocked_speed_mps);
  options.blocked_s = section.getPositive("blocked_s", options.blocked_s);
  options.back_off_speed_mps = section.getPositive("back_off_speed_mps", options.back_off_speed_mps);
  options.back_off_s = section.getPositive("back_off_s", options.back_off_s);
  // Converted only when given, so that the default stays exactly the radians above.
  if (section.has("facing_tolerance_deg")) {
    const double facing_deg = section.getPositive("facing_tolerance_deg", 0.0);
    if (facing_deg > 90.0) throw ConfigError("[" + section.name() + "] facing_tolerance_deg: must be at most 90");
    options.facing_tolerance_rad = facing_deg * M_PI / 180.0;
  }
  options.min_turn_rate = section.getPositive("min_turn_rate", options.min_turn_rate);
  options.turn_braking = section.getPositive("turn_braking", options.turn_braking);
  options.look_around_spacing_m = section.getNonNegative("look_around_spacing_m", options.look_around_spacing_m);
  options.escape_speed_mps = section.getPositive("escape_speed_mps", options.escape_speed_mps);
  options.resolving_views = section.getInt("resolving_views", options.resolving_views);
  if (options.resolving_views < 1) throw ConfigError("[" + section.name() + "] resolving_views: must be at least 1");
  options.look_hold_s = section.getNonNegative("look_hold_s", options.look_hold_s);
  options.arrived_m = section.getNonNegative("arrived_m", options.arrived_m);
  options.progress_m = section.getNonNegative("progress_m", options.progress_m);
  options.visit_spacing_m = section.getNonNegative("visit_spacing_m", options.visit_spacing_m);
  options.escape_search_m = section.getPositive("escape_search_m", options.escape_search_m);
  options.failed_escape_m = section.getNonNegative("failed_escape_m", options.failed_escape_m);
  options.speck_cells = section.getInt("speck_cells", options.speck_cells);
  if (options.speck_cells < 0) throw ConfigError("[" + section.name() + "] speck_cells: must not be negative");
  options.look_from_afar_m = section.getNonNegative("look_from_afar_m", options.look_from_afar_m);
  options.recovery_restarts = section.getInt("recovery_restarts", options.recovery_restarts);
  if (options.recovery_restarts < 0) {
    throw ConfigError("[" + section.name() + "] recovery_restarts: must not be negative");
  }
  options.recovery_restart_spacing_s =
      section.getNonNegative("recovery_restart_spacing_s", options.recovery_restart_spacing_s);
}

}  // namespace

ExplorerOptions loadExplorerOptions(IniSection& section) {
  ExplorerOptions options;
  options.robot_radius_m = section.getPositive("robot_radius_m", options.robot_radius_m);
  options.safety_margin_m = section.getNonNegative("safety_margin_m", options.safety_margin_m);
  options.repulsion_distance_m = section.getNonNegative("repulsion_distance_m", options.repulsion_distance_m);
  options.repulsion_weight = section.getNonNegative("repulsion_weight", options.repulsion_weight);
  options.max_hole_cells = section.getInt("max_hole_cells", options.max_hole_cells);
  if (options.max_hole_cells < 0) throw ConfigError("[" + section.name() + "] max_hole_cells: must not be negative");
  options.precise_min_disparity = section.getNonNegative("precise_min_disparity", options.precise_min_disparity);
  options.goal_distance_m = section.getPositive("goal_distance_m", options.goal_distance_m);
  options.min_frontier_cells = section.getInt("min_frontier_cells", options.min_frontier_cells);
  if (options.min_frontier_cells < 1) {
    throw ConfigError("[" + section.name() + "] min_frontier_cells: must be at least 1");
  }
  options.target_switch_penalty_m = section.getNonNegative("target_switch_penalty_m", options.target_switch_penalty_m);
  options.pocket_area_m2 = section.getNonNegative("pocket_area_m2", options.pocket_area_m2);
  options.pocket_penalty_m = section.getNonNegative("pocket_penalty_m", options.pocket_penalty_m);
  options.looked_at_range_m = section.getPositive("looked_at_range_m", options.looked_at_range_m);
  options.field_of_view_deg = section.getPositive("field_of_view_deg", options.field_of_view_deg);
  if (options.field_of_view_deg >= 180.0) {
    throw ConfigError("[" + section.name() + "] field_of_view_deg: must be below 180");
  }
  options.seen_free_range_m = section.getNonNegative("seen_free_range_m", options.seen_free_range_m);
  options.max_speed_mps = section.getPositive("max_speed_mps", options.max_speed_mps);
  options.max_turn_rate = section.getPositive("max_turn_rate", options.max_turn_rate);
  options.braking_deceleration = section.getPositive("braking_deceleration", options.braking_deceleration);
  options.heading_gain = section.getPositive("heading_gain", options.heading_gain);
  const double turn_in_place_deg = section.getPositive("turn_in_place_deg", options.turn_in_place_rad * 180.0 / M_PI);
  if (turn_in_place_deg > 90.0) {
    throw ConfigError("[" + section.name() + "] turn_in_place_deg: must be at most 90");
  }
  options.turn_in_place_rad = turn_in_place_deg * M_PI / 180.0;
  options.lookahead_m = section.getPositive("lookahead_m", options.lookahead_m);
  options.initial_look_around = section.getBool("initial_look_around", options.initial_look_around);
  options.look_around_turn_rate = section.getPositive("look_around_turn_rate", options.look_around_turn_rate);
  options.stuck_timeout_s = section.getPositive("stuck_timeout_s", options.stuck_timeout_s);
  options.guard_margin_m = section.getNonNegative("guard_margin_m", options.guard_margin_m);
  options.pass_beside_speed_mps = section.getPositive("pass_beside_speed_mps", options.pass_beside_speed_mps);
  options.obstacle_memory_range_m = section.getNonNegative("obstacle_memory_range_m", options.obstacle_memory_range_m);
  options.obstacle_memory_blind_m = section.getNonNegative("obstacle_memory_blind_m", options.obstacle_memory_blind_m);
  options.obstacle_memory_min_g = section.getInt("obstacle_memory_min_g", options.obstacle_memory_min_g);
  if (options.obstacle_memory_min_g < 0 || options.obstacle_memory_min_g > 255) {
    throw ConfigError("[" + section.name() + "] obstacle_memory_min_g: must be an occupancy value 0..255");
  }
  readPartTunables(section, options);
  if (options.obstacle_memory_blind_m > options.obstacle_memory_range_m) {
    throw ConfigError("[" + section.name() + "] obstacle_memory_blind_m: must not exceed obstacle_memory_range_m");
  }
  return options;
}

}  // namespace stereonav
