#include "closed_loop/exploration_benchmark.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "common/image_file.h"
#include "shipped_config.h"
#include "support/scratch_directory.h"

namespace stereonav {
namespace {

std::string readFile(const std::string& path) {
  std::ifstream file(path);
  return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

size_t count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// Two generated worlds x two seeds, a few simulated seconds each, two at a time: every run is in
// the table, the JSON, the summary and the montage, and its own outputs are beside them.
TEST(ExplorationBenchmarkTest, EveryRunIsTabledSummarisedAndDrawn) {
  const test_support::ScratchDirectory scratch;
  const std::filesystem::path& directory = scratch.path();
  ExplorationBenchmarkJob job;
  job.world_seeds = {2, 5};
  job.run_seeds = {1, 2};
  job.output_directory = directory.string();
  job.max_time_s = 6.0;
  job.parallel_runs = 2;
  size_t reported = 0;
  const std::vector<ExplorationBenchmarkRun> runs = runExplorationBenchmark(
      loadExplorationConfig(testing::shippedExplorationConfigPath()), job,
      [&](size_t done, size_t total) {
        EXPECT_EQ(total, 4u);
        reported = std::max(reported, done);
      });
  ASSERT_EQ(runs.size(), 4u);
  EXPECT_EQ(reported, 4u);
  for (const ExplorationBenchmarkRun& run : runs) {
    SCOPED_TRACE("world " + std::to_string(run.world_seed) + " seed " + std::to_string(run.run_seed));
    EXPECT_EQ(run.error, "");
    EXPECT_GT(run.report.coverage.coverage, 0.0);
    EXPECT_NEAR(run.report.sim_time_s, 6.0, 0.5);
    // Rendering is part of the run's time, not all of it.
    EXPECT_GT(run.report.render_wall_s, 0.0);
    EXPECT_LT(run.report.render_wall_s, run.report.wall_time_s);
    EXPECT_GT(run.report.speedUpWithoutRendering(), run.report.speedUp());
    const std::string prefix = (directory / ("world_" + std::to_string(run.world_seed) + "_seed_" +
                                             std::to_string(run.run_seed))).string();
    EXPECT_TRUE(std::filesystem::exists(prefix + ".path.png"));
    EXPECT_TRUE(std::filesystem::exists(prefix + ".stats.json"));
  }
  EXPECT_EQ(runs[0].world_kind, "apartment");  // seed 2 (the generator's own test pins its kinds)
  EXPECT_TRUE(std::filesystem::exists(directory / "world_5.ini"));
  EXPECT_TRUE(std::filesystem::exists(directory / "world_5.truth.yaml"));

  const std::string csv = readFile((directory / "runs.csv").string());
  EXPECT_EQ(count(csv, "\n"), 5u);  // the header and four runs
  EXPECT_EQ(csv.rfind("world,kind,seed,coverage,seen,time_to_80_s,time_to_90_s,time_to_95_s,", 0), 0u);
  EXPECT_EQ(count(readFile((directory / "runs.json").string()), "\"time_to_coverage_s\""), 4u);
  const std::string summary = readFile((directory / "summary.md").string());
  EXPECT_EQ(count(summary, "| apartment |") + count(summary, "| hall |"), 4u);
  EXPECT_NE(summary.find("4 runs: mean coverage"), std::string::npos);
  EXPECT_NE(summary.find("x without the simulator's rendering)"), std::string::npos);
  EXPECT_NE(csv.find(",wall_time_s,render_wall_s,"), std::string::npos);
  const cv::Mat montage = readImageFile((directory / "montage.png").string(), cv::IMREAD_COLOR);
  EXPECT_EQ(montage.cols, 2 * 320);  // two tiles a row
  EXPECT_EQ(montage.rows, 2 * (320 + 22));
}

}  // namespace
}  // namespace stereonav
