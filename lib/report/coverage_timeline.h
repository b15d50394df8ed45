#pragma once

#include <string>
#include <vector>

#include "closed_loop/exploration_config.h"
#include "simulator/world.h"

namespace stereonav {

// How much of the reachable free floor the map held at one moment of a run (exploration_coverage.h).
struct CoverageSample {
  double time_s = 0.0;
  double coverage = 0.0;       // mapped free / reachable free
  double seen_coverage = 0.0;  // known at all / reachable free
};

struct CoverageTimelineJob {
  std::string rawlog_path;    // recorded by `stereonav explore --record`, with its .gt.txt beside it
  std::string output_prefix;  // the replayed map's outputs (rawlog_mapping.h)
  std::string debug_panel_directory;  // "" = none
  size_t debug_panel_every = 1;
  double sample_period_s = 1.0;  // simulated time between samples (the last frame is always one)
};

// Replays a recorded exploration through the same mapping pipeline, with the poses the run mapped
// with (the true ones from the .gt.txt for pose_source = ground_truth, else the odometry), and
// measures the coverage against the world's ground truth as the map grew: the curve of which a
// run's stats.json holds only the end. The start for reachability is the first true pose.
// Throws std::runtime_error naming the file if the rawlog or its poses cannot be read.
std::vector<CoverageSample> replayCoverage(const ExplorationConfig& config, const World& world,
                                           const CoverageTimelineJob& job);

// "t,coverage,seen_coverage" and one line per sample.
std::string coverageCsv(const std::vector<CoverageSample>& samples);

}  // namespace stereonav
