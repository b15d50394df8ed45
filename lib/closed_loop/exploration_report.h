#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "evaluation/exploration_coverage.h"
#include "evaluation/trajectory_error.h"
#include "simulator/simulation.h"

namespace stereonav {

// What a closed-loop exploration achieved (<prefix>.stats.json).
struct ExplorationReport {
  // Coverage levels whose first reaching is timed.
  static constexpr std::array<double, 3> kCoverageMilestones{0.8, 0.9, 0.95};

  ExplorationCoverage coverage;
  // Simulated time at which the coverage first reached each milestone (measured every
  // ExplorationJob::coverage_sample_period_s); nothing if it never did.
  std::array<std::optional<double>, kCoverageMilestones.size()> time_to_coverage_s;
  double start_x = 0.0;
  double start_y = 0.0;
  double start_phi = 0.0;
  double distance_m = 0.0;
  double sim_time_s = 0.0;
  double wall_time_s = 0.0;
  // Of wall_time_s, the simulator drawing the camera images: what a robot with real cameras
  // would not spend. The rest is the robot's own software (stereo, mapping, explorer) and the
  // simulated motion.
  double render_wall_s = 0.0;
  double top_speed_mps = 0.0;
  double frame_rate_hz = 0.0;
  double pipeline_ms_per_frame = 0.0;  // the mapping pipeline alone
  size_t frames = 0;
  // Of the poses the map was built at against the true ones, one per frame (zero with true poses).
  TrajectoryError trajectory_error;
  size_t frames_localized = 0;  // frames the scan matching corrected (pose_source = localized)
  size_t frames_floor_measured = 0;  // frames whose step was measured on the floor (floor_motion)
  int collisions = 0;           // contacts the simulator counted (robot_options' footprint)
  std::vector<CollisionEvent> collision_events;
  int blocked_reversals = 0;    // times the explorer found itself blocked and reversed
  std::string stop_reason;
  bool interrupted = false;  // stopped by ExplorationCallbacks::stop_requested

  // Simulated seconds per wall-clock second, of the whole run and of the run without rendering.
  double speedUp() const;
  double speedUpWithoutRendering() const;

  std::string summary() const;
  std::string toJson() const;
};

}  // namespace stereonav
