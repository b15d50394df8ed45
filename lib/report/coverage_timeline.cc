#include "report/coverage_timeline.h"

#include <sstream>
#include <stdexcept>

#include "evaluation/exploration_coverage.h"
#include "mapping/map_outputs.h"
#include "mapping/rawlog_mapping.h"
#include "simulator/ground_truth_map.h"
#include "simulator/simulation_recorder.h"

namespace stereonav {

std::vector<CoverageSample> replayCoverage(const ExplorationConfig& config, const World& world,
                                           const CoverageTimelineJob& job) {
  const std::vector<mrpt::poses::CPose2D> true_poses =
      loadPoseList(SimulationRecorder::groundTruthPath(job.rawlog_path));
  if (true_poses.empty()) throw std::runtime_error(job.rawlog_path + ": the recorded run has no frame");
  const GroundTruthMap truth(world, config.simulator.ground_truth);
  const double frame_period_s = 1.0 / config.simulator.simulation.frame_rate_hz;
  const OccupancyScale& scale = config.mapping.grid.stereo.update.scale;

  MappingJob mapping;
  mapping.rawlog_path = job.rawlog_path;
  mapping.output_prefix = job.output_prefix;
  mapping.debug_panel_directory = job.debug_panel_directory;
  mapping.debug_panel_every = job.debug_panel_every;
  // The poses the run mapped with, so the replay rebuilds its map frame by frame.
  mapping.pose_source = config.pose_source;
  if (config.pose_source == MapPoseSource::kGroundTruth) mapping.ground_truth_poses = true_poses;

  std::vector<CoverageSample> samples;
  const ReachableFloor reachable(truth, config.simulator.robot.radius_m, true_poses.front().x(),
                                 true_poses.front().y());
  const auto sample = [&](double time_s, const mrpt::maps::CMetricMap& map) {
    const ExplorationCoverage coverage = reachable.measure(gridOfMap(map, scale));
    samples.push_back({time_s, coverage.coverage, coverage.seen_coverage});
  };
  MappingCallbacks callbacks;
  callbacks.on_frame = [&](size_t frames, const mrpt::maps::CMetricMap& map) {
    const double time_s = static_cast<double>(frames - 1) * frame_period_s;
    const bool last = frames == true_poses.size();
    if (samples.empty() || last || time_s >= samples.back().time_s + job.sample_period_s - 1e-9) sample(time_s, map);
  };
  const MappingReport report = mapRawlog(config.mapping, mapping, callbacks);
  if (!report.complete()) throw std::runtime_error(job.rawlog_path + ": damaged; replayed " +
                                                   std::to_string(report.frames_mapped) + " frames");
  return samples;
}

std::string coverageCsv(const std::vector<CoverageSample>& samples) {
  std::ostringstream csv;
  csv << "t,coverage,seen_coverage\n";
  for (const CoverageSample& sample : samples) {
    csv << sample.time_s << "," << sample.coverage << "," << sample.seen_coverage << "\n";
  }
  return csv.str();
}

}  // namespace stereonav
