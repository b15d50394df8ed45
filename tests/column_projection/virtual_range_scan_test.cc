#include "column_projection/virtual_range_scan.h"

#include <gtest/gtest.h>
#include <mrpt/maps/COccupancyGridMap2D.h>

#include <cmath>
#include <stdexcept>

#include "column_projection/column_projector.h"
#include "test_scenes.h"

namespace stereonav {
namespace {

constexpr double kDegree = M_PI / 180.0;

mrpt::obs::CObservation2DRangeScan levelCorridorScan(double max_range_m) {
  const CameraRig rig = testRig(0, 0, 0, 0);
  return makeVirtualRangeScan(ColumnProjector(rig, bodyVolume(0.95)).project(levelCorridor()), rig,
                              max_range_m);
}

TEST(VirtualRangeScanTest, RaysSpanTheHorizontalFieldOfViewCounterClockwise) {
  const auto scan = levelCorridorScan(10.0);
  ASSERT_EQ(scan.getScanSize(), 201u);
  EXPECT_TRUE(scan.rightToLeft);
  // Image edges at 100.5 px either side of the centre: 2 atan(1.005) = 90.2857 degrees.
  EXPECT_NEAR(scan.aperture, 90.2857 * kDegree, 1e-4);
  EXPECT_NEAR(scan.getScanAngle(0), -45.1429 * kDegree, 1e-4);  // rightmost ray
  EXPECT_NEAR(scan.getScanAngle(100), 0.0, 1e-6);
  EXPECT_NEAR(scan.getScanAngle(36), -28.8915 * kDegree, 1e-4);  // -45.1429 + 36 * 0.451429
  EXPECT_NEAR(scan.getScanAngle(150), 22.5714 * kDegree, 1e-4);
  EXPECT_FLOAT_EQ(scan.maxRange, 10.0f);
}

TEST(VirtualRangeScanTest, RangesAreHorizontalDistancesOfTheColumnsObstacles) {
  const auto scan = levelCorridorScan(10.0);
  // Ray 100 looks down column 100: the wall straight ahead at 2 m.
  ASSERT_TRUE(scan.getScanRangeValidity(100));
  EXPECT_NEAR(scan.getScanRange(100), 2.0, 1e-5);
  // Ray 36 (-28.89 deg) passes through column 100 + 100 tan(28.89) = 155.17, i.e. pixel 155: the
  // box, Z = 1.25 m, 55 * 1.25 / 100 = 0.6875 m to the right: hypot(1.25, 0.6875) = 1.42663 m.
  ASSERT_TRUE(scan.getScanRangeValidity(36));
  EXPECT_NEAR(scan.getScanRange(36), 1.42663, 1e-4);
  // Ray 150 (22.57 deg) passes through column 100 - 41.57 = 58.43, pixel 58: the wall at 2 m,
  // 42 * 2 / 100 = 0.84 m to the left: hypot(2, 0.84) = 2.16924 m.
  ASSERT_TRUE(scan.getScanRangeValidity(150));
  EXPECT_NEAR(scan.getScanRange(150), 2.16924, 1e-4);
}

TEST(VirtualRangeScanTest, EveryRayEndsOnTheWallOrTheBoxFace) {
  const auto scan = levelCorridorScan(10.0);
  for (size_t i = 1; i + 1 < scan.getScanSize(); ++i) {
    ASSERT_TRUE(scan.getScanRangeValidity(i)) << "ray " << i;
    const double ahead = scan.getScanRange(i) * std::cos(scan.getScanAngle(i));
    // Half a pixel of bearing error moves the end point along the surface, not off it by much.
    const double to_surface = std::min(std::abs(ahead - 2.0), std::abs(ahead - 1.25));
    EXPECT_LT(to_surface, 0.02) << "ray " << i;
  }
}

TEST(VirtualRangeScanTest, ObstaclesBeyondMaxRangeLeaveTheirRaysInvalid) {
  const auto scan = levelCorridorScan(1.5);
  EXPECT_FALSE(scan.getScanRangeValidity(100));  // the wall, 2 m
  EXPECT_FLOAT_EQ(scan.getScanRange(100), 1.5f);
  EXPECT_TRUE(scan.getScanRangeValidity(36));  // the box, 1.43 m
}

TEST(VirtualRangeScanTest, SensorPoseIsTheCameraDroppedOnTheFloorWithItsHeading) {
  const CameraRig rig = testRig(0.2, 0.1, 10.0, 30.0);
  DisparityScan empty;
  empty.column_disparity.assign(201, kInvalidDisparity);
  empty.column_row.assign(201, -1);
  const auto scan = makeVirtualRangeScan(empty, rig, 5.0);
  EXPECT_NEAR(scan.sensorPose.x(), 0.2, 1e-9);
  EXPECT_NEAR(scan.sensorPose.y(), 0.1, 1e-9);
  EXPECT_NEAR(scan.sensorPose.z(), 0.0, 1e-9);
  EXPECT_NEAR(scan.sensorPose.yaw(), 10.0 * kDegree, 1e-9);
  EXPECT_NEAR(scan.sensorPose.pitch(), 0.0, 1e-9);
  EXPECT_NEAR(scan.sensorPose.roll(), 0.0, 1e-9);
  for (size_t i = 0; i < scan.getScanSize(); ++i) EXPECT_FALSE(scan.getScanRangeValidity(i));
}

TEST(VirtualRangeScanTest, TiltedCameraRaysEndOnTheBoxFaceWithoutGaps) {
  const CameraRig rig = testRig(0, 0, 0, 30);
  const auto scan = makeVirtualRangeScan(
      ColumnProjector(rig, bodyVolume(1.0)).project(tiltedFloorWithBox()), rig, 10.0);
  // Straight ahead: the box face, 1 m in front of the camera.
  ASSERT_TRUE(scan.getScanRangeValidity(100));
  EXPECT_NEAR(scan.getScanRange(100), 1.0, 1e-4);
  size_t first = scan.getScanSize(), last = 0;
  for (size_t i = 0; i < scan.getScanSize(); ++i) {
    if (!scan.getScanRangeValidity(i)) continue;
    first = std::min(first, i);
    last = std::max(last, i);
    const double ahead = scan.getScanRange(i) * std::cos(scan.getScanAngle(i));
    const double left = scan.getScanRange(i) * std::sin(scan.getScanAngle(i));
    EXPECT_NEAR(ahead, 1.0, 0.01) << "ray " << i;
    EXPECT_LE(std::abs(left), 0.2 + 0.01) << "ray " << i;
  }
  ASSERT_LT(first, last);
  // The box is 0.4 m wide at 1 m: about 2 atan(0.2) = 22.6 degrees of rays, all of them valid.
  EXPECT_NEAR((last - first) * scan.aperture / (scan.getScanSize() - 1), 22.6 * kDegree,
              2.0 * kDegree);
  for (size_t i = first; i <= last; ++i) EXPECT_TRUE(scan.getScanRangeValidity(i)) << "ray " << i;
}

TEST(VirtualRangeScanTest, StockMrptGridMapsTheWallAndTheFreeSpaceBeforeIt) {
  const auto scan = levelCorridorScan(10.0);
  mrpt::maps::COccupancyGridMap2D grid(-3.0f, 3.0f, -3.0f, 3.0f, 0.05f);
  // A column without an obstacle means "nothing matched", not "nothing there".
  grid.insertionOptions.considerInvalidRangesAsFreeSpace = false;
  for (int i = 0; i < 5; ++i) ASSERT_TRUE(grid.insertObservation(scan, mrpt::poses::CPose3D()));
  // MRPT grid cells hold the probability of being free.
  EXPECT_LT(grid.getPos(2.02f, 0.0f), 0.4f);  // the wall, 2 m ahead
  EXPECT_GT(grid.getPos(1.0f, 0.0f), 0.6f);   // seen through
  // The box face, 1.25 m ahead, 0.6875 m to the right (ray 36, column 155); the ray ends
  // 1.249 m ahead, in the cell just short of 1.25.
  EXPECT_LT(grid.getPos(1.24f, -0.69f), 0.4f);
  EXPECT_NEAR(grid.getPos(-1.0f, 0.0f), 0.5f, 0.01f);  // behind the camera: unknown
}

TEST(VirtualRangeScanTest, RejectsScanWithoutRows) {
  DisparityScan scan;
  scan.column_disparity.assign(201, 5.0f);
  EXPECT_THROW(makeVirtualRangeScan(scan, testRig(0, 0, 0, 0), 10.0), std::invalid_argument);
}

}  // namespace
}  // namespace stereonav
