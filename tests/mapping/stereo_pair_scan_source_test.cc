#include "mapping/stereo_pair_scan_source.h"

#include <gtest/gtest.h>
#include <mrpt/obs/CObservationOdometry.h>

#include "observations/rig_observations.h"
#include "occupancy_grid/stereo_occupancy_grid_map.h"
#include "synthetic_scene.h"

namespace stereonav {
namespace {

using testing::SyntheticScene;
using testing::Wall;

TEST(StereoPairScanSourceTest, StereoOccupancyGridMapTakesARawStereoPair) {
  // The pair of a Triclops frame: reference (right) camera and the left camera beside it.
  const SyntheticScene scene({Wall{2.0, -3.0, 2.0, 3.0}});
  const RigFrame frame = scene.renderFrame(testing::testRig(), {}, mrpt::Clock::fromDouble(5.0));
  const RigObservations observations = toRigObservations(frame, "TRICLOPS");

  MappingOptions options;
  CStereoOccupancyGridMap map(options.grid.stereo);
  EXPECT_FALSE(map.insertObservation(*observations.pair));  // no source yet: refused
  map.addDisparityScanSource(std::make_shared<StereoPairScanSource>(options));
  for (int i = 0; i < 6; ++i) EXPECT_TRUE(map.insertObservation(*observations.pair));
  EXPECT_FALSE(map.insertObservation(mrpt::obs::CObservationOdometry()));  // still refused

  int col, row;
  double wall = 0.0;
  for (double x = 1.9; x <= 2.1; x += 0.01) {
    ASSERT_TRUE(map.grid().cellAt(x, 0.0, col, row));
    wall = std::max<double>(wall, map.grid().occupancy(col, row));
  }
  EXPECT_GT(wall, 150.0);
  ASSERT_TRUE(map.grid().cellAt(1.0, 0.0, col, row));
  EXPECT_LT(map.grid().occupancy(col, row), 50);
}

TEST(StereoPairScanSourceTest, ScanOfAPairCarriesTheCameraAndTheWallDisparity) {
  const SyntheticScene scene({Wall{2.0, -3.0, 2.0, 3.0}});
  const CameraRig rig = testing::testRig();
  const RigFrame frame = scene.renderFrame(rig, {}, mrpt::Clock::fromDouble(5.0));
  const StereoPairScanSource source{MappingOptions{}};
  const auto scan = source.toDisparityScan(*toRigObservations(frame, "TRICLOPS").pair);
  ASSERT_TRUE(scan);
  EXPECT_EQ(scan->timestamp, frame.timestamp);
  EXPECT_NEAR(scan->camera.focal_px, rig.reference.focal_px, 1e-9);
  EXPECT_NEAR(scan->camera.baseline_m, rig.baseline_m, 1e-9);
  EXPECT_NEAR(scan->camera.pose_on_robot.z(), 0.5, 1e-9);
  // d = f B / Z = 160 * 0.1 / 2 = 8 in the middle column.
  ASSERT_EQ(scan->scan.columns(), rig.reference.width);
  EXPECT_NEAR(scan->scan.column_disparity[rig.reference.width / 2], 8.0, 0.5);
  EXPECT_EQ(source.toDisparityScan(mrpt::obs::CObservationOdometry()), nullptr);
}

}  // namespace
}  // namespace stereonav
