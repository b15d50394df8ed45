#include "localization/localization_options.h"

namespace stereonav {

LocalizationOptions loadLocalizationOptions(IniSection& section) {
  LocalizationOptions options;
  options.max_range_m = section.getPositive("max_range_m", options.max_range_m);
  options.point_spacing_m = section.getNonNegative("point_spacing_m", options.point_spacing_m);
  options.disparity_sigma_px = section.getNonNegative("disparity_sigma_px", options.disparity_sigma_px);
  options.min_point_sigma_m = section.getPositive("min_point_sigma_m", options.min_point_sigma_m);
  options.outlier_probability = section.getPositive("outlier_probability", options.outlier_probability);
  if (!(options.outlier_probability < 1.0)) {
    throw ConfigError("[" + section.name() + "] outlier_probability: must be in (0, 1)");
  }
  options.window_m = section.getNonNegative("window_m", options.window_m);
  options.window_deg = section.getNonNegative("window_deg", options.window_deg);
  options.step_m = section.getPositive("step_m", options.step_m);
  options.step_deg = section.getPositive("step_deg", options.step_deg);
  options.prior_sigma_m = section.getPositive("prior_sigma_m", options.prior_sigma_m);
  options.prior_sigma_m_per_m = section.getNonNegative("prior_sigma_m_per_m", options.prior_sigma_m_per_m);
  options.prior_sigma_deg = section.getPositive("prior_sigma_deg", options.prior_sigma_deg);
  options.prior_sigma_per_rad = section.getNonNegative("prior_sigma_per_rad", options.prior_sigma_per_rad);
  options.min_matched_points = section.getInt("min_matched_points", options.min_matched_points);
  if (options.min_matched_points < 1) {
    throw ConfigError("[" + section.name() + "] min_matched_points: must be >= 1");
  }
  options.min_matched_fraction = section.getNonNegative("min_matched_fraction", options.min_matched_fraction);
  if (options.min_matched_fraction > 1.0) {
    throw ConfigError("[" + section.name() + "] min_matched_fraction: must be in [0, 1]");
  }
  options.max_spread = section.getPositive("max_spread", options.max_spread);
  FloorMotionOptions& floor = options.floor;
  floor.enabled = section.getBool("floor_motion", floor.enabled);
  WallHeadingOptions& walls = options.walls;
  WallPositionOptions& position = options.wall_position;
  // The filters' scales of odometry are there to learn the wheels' (a wheel base or radius off
  // its nominal length). The floor measures those itself and its own steps have none, so the
  // filters' scales could only fit the walls' errors: on the office replays a distance scale
  // learned 0.3% short shrank the whole map (docs/localization.md, session 76).
  if (floor.enabled) {
    walls.turn_scale_sigma = 0.0;
    position.distance_scale_sigma = 0.0;
  }
  walls.segments.max_range_m = section.getNonNegative("wall_max_range_m", walls.segments.max_range_m);
  walls.segments.max_gap_m = section.getPositive("wall_max_gap_m", walls.segments.max_gap_m);
  walls.segments.split_tolerance_m = section.getPositive("wall_split_tolerance_m", walls.segments.split_tolerance_m);
  walls.segments.min_points = section.getInt("wall_min_points", walls.segments.min_points);
  if (walls.segments.min_points < 3) throw ConfigError("[" + section.name() + "] wall_min_points: must be >= 3");
  walls.segments.min_length_m = section.getPositive("wall_min_length_m", walls.segments.min_length_m);
  walls.min_sigma_deg = section.getPositive("wall_min_sigma_deg", walls.min_sigma_deg);
  walls.heading_noise_deg_per_frame =
      section.getPositive("heading_noise_deg_per_frame", walls.heading_noise_deg_per_frame);
  walls.heading_noise_per_rad = section.getNonNegative("heading_noise_per_rad", walls.heading_noise_per_rad);
  walls.heading_noise_deg_per_m = section.getNonNegative("heading_noise_deg_per_m", walls.heading_noise_deg_per_m);
  walls.turn_scale_sigma = section.getNonNegative("turn_scale_sigma", walls.turn_scale_sigma);
  walls.gate_sigmas = section.getPositive("wall_gate_sigmas", walls.gate_sigmas);
  walls.max_correction_deg = section.getPositive("wall_max_correction_deg", walls.max_correction_deg);
  if (!(walls.max_correction_deg < 45.0)) {
    throw ConfigError("[" + section.name() + "] wall_max_correction_deg: must be below 45 (walls pair at 90 degrees)");
  }
  walls.new_direction_segments = section.getInt("wall_new_direction_segments", walls.new_direction_segments);
  if (walls.new_direction_segments < 1) {
    throw ConfigError("[" + section.name() + "] wall_new_direction_segments: must be >= 1");
  }
  walls.new_direction_spread_deg = section.getPositive("wall_new_direction_spread_deg", walls.new_direction_spread_deg);
  walls.agreeing_segments = section.getInt("wall_agreeing_segments", walls.agreeing_segments);
  if (walls.agreeing_segments < 1) throw ConfigError("[" + section.name() + "] wall_agreeing_segments: must be >= 1");
  position.enabled = section.getBool("wall_offsets", position.enabled);
  position.position_noise_per_m = section.getNonNegative("position_noise_per_m", position.position_noise_per_m);
  position.distance_scale_sigma = section.getNonNegative("distance_scale_sigma", position.distance_scale_sigma);
  position.min_offset_sigma_m = section.getPositive("wall_min_offset_sigma_m", position.min_offset_sigma_m);
  position.max_join_gap_m = section.getNonNegative("wall_max_join_gap_m", position.max_join_gap_m);
  floor.min_range_m = section.getNonNegative("floor_min_range_m", floor.min_range_m);
  floor.max_range_m = section.getPositive("floor_max_range_m", floor.max_range_m);
  if (!(floor.max_range_m > floor.min_range_m)) {
    throw ConfigError("[" + section.name() + "] floor_max_range_m: must be above floor_min_range_m");
  }
  floor.disparity_tolerance_px = section.getPositive("floor_disparity_tolerance_px", floor.disparity_tolerance_px);
  floor.pixel_step = section.getInt("floor_pixel_step", floor.pixel_step);
  if (floor.pixel_step < 1) throw ConfigError("[" + section.name() + "] floor_pixel_step: must be >= 1");
  floor.min_pixels = section.getInt("floor_min_pixels", floor.min_pixels);
  if (floor.min_pixels < 10) throw ConfigError("[" + section.name() + "] floor_min_pixels: must be >= 10");
  floor.max_disagreement_m = section.getNonNegative("floor_max_disagreement_m", floor.max_disagreement_m);
  floor.max_disagreement_deg = section.getNonNegative("floor_max_disagreement_deg", floor.max_disagreement_deg);
  floor.max_disagreement_fraction =
      section.getNonNegative("floor_max_disagreement_fraction", floor.max_disagreement_fraction);
  floor.wheel_turn_scale_sigma = section.getNonNegative("floor_wheel_turn_scale_sigma", floor.wheel_turn_scale_sigma);
  floor.wheel_turn_noise_per_rad =
      section.getNonNegative("floor_wheel_turn_noise_per_rad", floor.wheel_turn_noise_per_rad);
  floor.wheel_heading_noise_deg_per_m =
      section.getNonNegative("floor_wheel_heading_noise_deg_per_m", floor.wheel_heading_noise_deg_per_m);
  return options;
}

}  // namespace stereonav
