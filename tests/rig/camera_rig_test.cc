#include "rig/camera_rig.h"

#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/core/bits_math.h>

namespace stereonav {
namespace {

TEST(CameraRigTest, DepthFromDisparityIsFocalTimesBaselineOverDisparity) {
  CameraRig rig;
  rig.reference.focal_px = 200.0;
  rig.baseline_m = 0.1;
  EXPECT_DOUBLE_EQ(rig.depthForDisparity(10.0), 2.0);  // 200 * 0.1 / 10
  EXPECT_DOUBLE_EQ(rig.disparityForDepth(2.0), 10.0);
}

TEST(CameraRigTest, OpticalAxisLooksAlongRobotXAtMountHeight) {
  const auto pose = CameraRig::opticalPoseOnRobot(0.2, 0.0, 0.5, 0.0, 0.0);
  // A point 3 m in front of the camera on its optical axis is 3.2 m ahead of the robot at 0.5 m.
  const auto ahead = pose.composePoint({0.0, 0.0, 3.0});
  EXPECT_NEAR(ahead.x, 3.2, 1e-12);
  EXPECT_NEAR(ahead.y, 0.0, 1e-12);
  EXPECT_NEAR(ahead.z, 0.5, 1e-12);
  // Image x (right) is the robot's -y; image y (down) is the robot's -z.
  const auto right = pose.composePoint({1.0, 0.0, 0.0});
  EXPECT_NEAR(right.y, -1.0, 1e-12);
  const auto down = pose.composePoint({0.0, 1.0, 0.0});
  EXPECT_NEAR(down.z, -0.5, 1e-12);
}

TEST(CameraRigTest, TiltDownLowersTheOpticalAxis) {
  const auto pose = CameraRig::opticalPoseOnRobot(0.0, 0.0, 1.0, 0.0, mrpt::DEG2RAD(45.0));
  const auto ahead = pose.composePoint({0.0, 0.0, std::sqrt(2.0)});
  EXPECT_NEAR(ahead.x, 1.0, 1e-12);
  EXPECT_NEAR(ahead.z, 0.0, 1e-12);
}

TEST(CameraRigTest, YawTurnsTheOpticalAxisLeft) {
  const auto pose = CameraRig::opticalPoseOnRobot(0.0, 0.0, 0.0, mrpt::DEG2RAD(90.0), 0.0);
  const auto ahead = pose.composePoint({0.0, 0.0, 1.0});
  EXPECT_NEAR(ahead.x, 0.0, 1e-12);
  EXPECT_NEAR(ahead.y, 1.0, 1e-12);
}

TEST(CameraRigTest, ARayThroughAPixelIsItsOffsetPerUnitOfDepthOnTheRobot) {
  CameraRig rig;  // level, looking along the robot's x
  rig.reference.focal_px = 100.0;
  rig.reference.cx = 50.0;
  rig.reference.cy = 40.0;
  const auto centre = rig.rayOnRobot(50.0, 40.0);
  EXPECT_NEAR(centre.x, 1.0, 1e-12);
  EXPECT_NEAR(centre.y, 0.0, 1e-12);
  EXPECT_NEAR(centre.z, 0.0, 1e-12);
  // A focal length right of and half of one below the principal point: 45 degrees to the right
  // and half a unit down per unit of depth.
  const auto right_below = rig.rayOnRobot(150.0, 90.0);
  EXPECT_NEAR(right_below.x, 1.0, 1e-12);
  EXPECT_NEAR(right_below.y, -1.0, 1e-12);
  EXPECT_NEAR(right_below.z, -0.5, 1e-12);
  // Tilted down 45 degrees, the principal point's ray drops as fast as it goes forward; both per
  // unit of depth along the tilted axis, sqrt(1/2) each.
  rig.pose_on_robot = CameraRig::opticalPoseOnRobot(0.0, 0.0, 1.0, 0.0, mrpt::DEG2RAD(45.0));
  const auto tilted = rig.rayOnRobot(50.0, 40.0);
  EXPECT_NEAR(tilted.x, std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(tilted.z, -std::sqrt(0.5), 1e-12);
}

TEST(CameraRigTest, LoadsFromIni) {
  mrpt::config::CConfigFileMemory config(
      "[rig]\nwidth = 160\nheight = 120\nfocal_px = 80\nbaseline_m = 0.1\n"
      "secondary_cameras = -1 0; 0 -1\nmount_z = 0.9\n");
  IniSection section(config, "rig");
  const CameraRig rig = loadCameraRig(section);
  section.rejectUnknownKeys();
  EXPECT_EQ(rig.reference.width, 160);
  EXPECT_DOUBLE_EQ(rig.reference.cx, 79.5);
  ASSERT_EQ(rig.secondaries.size(), 2u);
  EXPECT_DOUBLE_EQ(rig.secondaries[0].bx, -1.0);
  EXPECT_DOUBLE_EQ(rig.secondaries[1].by, -1.0);
  EXPECT_NEAR(rig.pose_on_robot.z(), 0.9, 1e-12);
}

TEST(CameraRigTest, MalformedSecondaryCamerasAreRejected) {
  EXPECT_THROW(parseSecondaryCameras("1", "cams"), ConfigError);
  EXPECT_THROW(parseSecondaryCameras("1 0 2", "cams"), ConfigError);
  EXPECT_THROW(parseSecondaryCameras("0 0", "cams"), ConfigError);
  EXPECT_THROW(parseSecondaryCameras("", "cams"), ConfigError);
  EXPECT_EQ(parseSecondaryCameras("-2 0; -1 0; 1 0; 2 0; 0.5 0", "cams").size(), 5u);
}

}  // namespace
}  // namespace stereonav
