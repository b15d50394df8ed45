#pragma once

#include "common/ini_section.h"
#include "localization/floor_motion.h"
#include "localization/wall_heading_filter.h"
#include "localization/wall_position_filter.h"

namespace stereonav {

// How ScanLocalizer corrects odometry by each stereo scan (section [localization]): the
// correlative matcher against the map built so far, then the heading by the walls' directions
// and the position by the walls' offsets.
// The paper maps with dead reckoning and names its drift as the open problem (section 5).
struct LocalizationOptions {
  // Only readings nearer than this take part: a stereo reading's range error grows with the
  // square of its range (Z^2 / (f B) per pixel of disparity, paper section 3.2), so far ones
  // would pull the match more than they can tell.
  double max_range_m = 2.5;
  // Readings are thinned to one per this distance along the scan, so a near wall seen by many
  // columns does not outvote the rest.
  double point_spacing_m = 0.05;
  // A reading's range uncertainty: disparity_sigma_px of disparity at its range, and never less
  // than min_point_sigma_m (the map's cells quantise obstacles too).
  double disparity_sigma_px = 0.3;
  double min_point_sigma_m = 0.05;
  // The chance that a reading matches nothing in the map (new obstacles, mismatches): caps the
  // penalty a single reading can give a pose.
  double outlier_probability = 0.2;
  // The poses tried around the odometry prediction: +/- window, in steps. Both windows 0: no
  // matching, the pose is odometry's with the walls' heading.
  double window_m = 0.3;
  double window_deg = 10.0;
  double step_m = 0.025;
  double step_deg = 1.0;
  // How far odometry is trusted between two frames, a Gaussian prior on the correction: its
  // sigma is prior_sigma_m plus prior_sigma_m_per_m of the distance driven since the last frame,
  // and prior_sigma_deg plus prior_sigma_per_rad of the angle turned (radians per radian).
  double prior_sigma_m = 0.02;
  double prior_sigma_m_per_m = 0.1;
  double prior_sigma_deg = 1.0;
  double prior_sigma_per_rad = 0.1;
  // Fewer matched readings than this (within 3 sigma of a map obstacle at the best pose), or a
  // smaller fraction of the readings: keep odometry (the scan sees mostly what the map has not).
  int min_matched_points = 10;
  double min_matched_fraction = 0.5;
  // A direction of the pose is corrected only if the match pins it down: the spread of the
  // scan's likelihood along it, as a fraction of the window, is below this. Along a straight
  // corridor the likelihood is flat and the position along it keeps odometry.
  double max_spread = 0.1;
  // Keys wall_max_range_m, wall_max_gap_m, wall_split_tolerance_m, wall_min_points,
  // wall_min_length_m, wall_min_sigma_deg, heading_noise_deg_per_frame, heading_noise_per_rad,
  // heading_noise_deg_per_m, turn_scale_sigma, wall_gate_sigmas, wall_max_correction_deg,
  // wall_new_direction_segments, wall_new_direction_spread_deg, wall_agreeing_segments.
  // wall_max_range_m = 0: no walls. With floor_motion, turn_scale_sigma and distance_scale_sigma
  // default to 0: the floor measures odometry's scales.
  WallHeadingOptions walls;
  // Keys wall_offsets (true/false), position_noise_per_m, distance_scale_sigma,
  // wall_min_offset_sigma_m, wall_max_join_gap_m.
  WallPositionOptions wall_position;
  // Keys floor_motion (true/false), floor_min_range_m, floor_max_range_m,
  // floor_disparity_tolerance_px, floor_pixel_step, floor_min_pixels, floor_max_disagreement_m,
  // floor_max_disagreement_deg, floor_max_disagreement_fraction, floor_wheel_turn_scale_sigma.
  FloorMotionOptions floor;

  bool matches() const { return window_m > 0.0 || window_deg > 0.0; }
};

// Keys as the member names; all optional, steps and windows positive.
LocalizationOptions loadLocalizationOptions(IniSection& section);

}  // namespace stereonav
