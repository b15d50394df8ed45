// End to end: the shipped simulated office run mapped with its true poses by the shipped
// configuration, scored against the simulator's true map.

#include <gtest/gtest.h>

#include <iostream>

#include "evaluation/map_score.h"
#include "occupancy_grid/ros_map.h"
#include "evaluation/trajectory_error.h"
#include "mapping/mapping_options.h"
#include "mapping/rawlog_mapping.h"
#include "support/scratch_directory.h"

namespace stereonav {
namespace {

const std::string kSourceDir = STEREONAV_SOURCE_DIR;

class OfficeRunTest : public ::testing::Test {
 protected:

  // Maps the run with ini/office_run.ini changed by `adjust`, and scores the map.
  template <typename Adjust>
  MapScore mapAndScore(Adjust adjust, MapPoseSource poses = MapPoseSource::kGroundTruth) {
    MappingOptions options = loadMappingOptionsFile(kSourceDir + "/ini/office_run.ini");
    adjust(options);
    MappingJob job;
    job.rawlog_path = kSourceDir + "/rawlogs/office_run.rawlog";
    job.output_prefix = scratch_.file("office");
    job.pose_source = poses;
    job.ground_truth_poses = loadPoseList(kSourceDir + "/rawlogs/office_run.gt.txt");
    const MappingReport report = mapRawlog(options, job);
    EXPECT_TRUE(report.complete());
    EXPECT_EQ(report.frames_mapped, job.ground_truth_poses.size());
    last_path_ = report.path;

    MapScoreOptions score_options;
    score_options.poses = job.ground_truth_poses;
    // Obstacles count for recall as far as the configuration maps them.
    score_options.view_range_m = options.projection.max_depth_m;
    return scoreMap(loadRosMap(job.output_prefix + ".yaml"),
                    loadRosMap(kSourceDir + "/rawlogs/office_run.truth.yaml"), score_options);
  }

  test_support::ScratchDirectory scratch_;
  std::vector<mrpt::poses::CPose2D> last_path_;
};

TEST_F(OfficeRunTest, ShippedConfigurationMapsTheOfficeWalls) {
  const MapScore score = mapAndScore([](MappingOptions&) {});
  std::cout << score.toText();
  // Walls within one 10 cm cell (issue 5's targets: precision 0.90, recall 0.80, false free
  // 0.5%). What keeps precision there is the row-aware sensor model, the median of a column's
  // nearest surface and the sub-pixel region of uncertainty (see ini/office_run.ini); what
  // keeps the cells at the meeting room's chairs out of the free space is that a scan leaves
  // the cells touching its own obstacles alone (the camera sees past and under the seats,
  // paper section 6.1).
  EXPECT_GE(score.precision(), 0.90);
  EXPECT_GE(score.recall(), 0.80);
  EXPECT_LE(score.falseFree(), 0.005);
  EXPECT_GT(score.coverage(), 0.0);
}

TEST_F(OfficeRunTest, LocalizedPosesMapAsWellAsTheTrueOnes) {
  // The run's odometry is the simulator's (2 % per metre): localizing by scan matching must not
  // make it worse, and the map from the localized poses scores within 0.03 of the true-pose map.
  const MapScore truth = mapAndScore([](MappingOptions&) {});
  const MapScore localized = mapAndScore([](MappingOptions&) {}, MapPoseSource::kLocalized);
  const TrajectoryError error =
      trajectoryError(last_path_, loadPoseList(kSourceDir + "/rawlogs/office_run.gt.txt"));
  std::cout << localized.toText() << error.toText();
  EXPECT_NEAR(localized.precision(), truth.precision(), 0.03);
  EXPECT_NEAR(localized.recall(), truth.recall(), 0.03);
  EXPECT_LE(error.rms_m, 0.05);
  EXPECT_LE(error.max_m, 0.15);
}

TEST_F(OfficeRunTest, FarReadingsMarkCellsBehindTheWalls) {
  // Without the depth limit the deep regions of far readings cover the rooms behind the walls.
  const MapScore limited = mapAndScore([](MappingOptions&) {});
  const MapScore unlimited = mapAndScore([](MappingOptions& options) { options.projection.max_depth_m = 0.0; });
  EXPECT_LT(unlimited.precision(), 0.5);
  EXPECT_GT(unlimited.map_occupied, 4 * limited.map_occupied);
}

TEST_F(OfficeRunTest, AccuracyPreservationKeepsFarReadingsFromThickeningNearWalls) {
  // Paper section 4.3, at full range where far readings overlap near ones.
  const MapScore with = mapAndScore([](MappingOptions& options) { options.projection.max_depth_m = 0.0; });
  const MapScore without = mapAndScore([](MappingOptions& options) {
    options.projection.max_depth_m = 0.0;
    options.grid.stereo.update.accuracy_preservation = false;
  });
  EXPECT_GT(with.precision(), without.precision());
  EXPECT_LT(with.map_occupied, without.map_occupied);
}

}  // namespace
}  // namespace stereonav
