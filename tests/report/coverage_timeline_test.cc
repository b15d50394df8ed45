#include "report/coverage_timeline.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "closed_loop/exploration_run.h"
#include "simulator/world_loader.h"

namespace stereonav {
namespace {

// The replay maps the recording to the run's own map, so its last sample is the coverage the run
// reported at its end, and the samples lie one simulated second apart.
TEST(ReplayCoverage, EndsAtTheRunsOwnCoverageWithASampleEachSecond) {
  const std::string directory = std::string(STEREONAV_BINARY_DIR) + "/test_outputs/report/room";
  std::filesystem::remove_all(directory);
  std::filesystem::create_directories(directory + "/panels");
  const std::string ini = std::string(STEREONAV_TEST_DATA_DIR) + "/../../ini/";
  const World world = loadWorld(ini + "worlds/table_room.ini");
  const ExplorationConfig config = loadExplorationConfig(ini + "explore_160x120.ini");
  ExplorationJob run;
  run.output_prefix = directory + "/run";
  run.record_rawlog = directory + "/run.rawlog";
  run.max_time_s = 6.0;
  const ExplorationReport report = runExploration(world, config, run);

  CoverageTimelineJob job;
  job.rawlog_path = run.record_rawlog;
  job.output_prefix = directory + "/replay";
  job.debug_panel_directory = directory + "/panels";
  job.debug_panel_every = 10;
  const std::vector<CoverageSample> samples = replayCoverage(config, world, job);

  ASSERT_GE(samples.size(), 6u);
  EXPECT_NEAR(samples.back().coverage, report.coverage.coverage, 1e-9);
  EXPECT_NEAR(samples.back().seen_coverage, report.coverage.seen_coverage, 1e-9);
  const double frame_period_s = 1.0 / config.simulator.simulation.frame_rate_hz;
  EXPECT_NEAR(samples.back().time_s, static_cast<double>(report.frames - 1) * frame_period_s, 1e-9);
  for (size_t i = 0; i + 1 < samples.size(); ++i) {
    EXPECT_NEAR(samples[i].time_s, static_cast<double>(i), 1e-9) << i;
  }
  EXPECT_LT(samples.front().coverage, samples.back().coverage);
  size_t panels = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(job.debug_panel_directory)) ++panels;
  EXPECT_EQ(panels, (report.frames + 9) / 10);
}

}  // namespace
}  // namespace stereonav
