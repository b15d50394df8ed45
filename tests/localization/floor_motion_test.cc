#include "localization/floor_motion.h"

#include <gtest/gtest.h>

#include <mrpt/core/bits_math.h>
#include <mrpt/math/wrap2pi.h>

#include <cmath>

#include "disparity/disparity_image.h"

namespace stereonav {
namespace {

// A 320 x 240 head 0.5 m up, looking 30 degrees down at the floor.
CameraRig floorRig() {
  CameraRig rig;
  rig.pose_on_robot = CameraRig::opticalPoseOnRobot(0.1, 0.0, 0.5, 0.0, mrpt::DEG2RAD(30.0));
  return rig;
}

// The floor's brightness at world point (x, y): waves of several lengths and directions, so
// that every motion changes what each pixel sees.
double floorTexture(double x, double y) {
  return 128.0 + 35.0 * std::sin(9.0 * x + 4.0 * y) + 30.0 * std::sin(-6.0 * x + 11.0 * y + 1.0) +
         20.0 * std::sin(17.0 * x - 13.0 * y + 2.0) + 15.0 * std::sin(23.0 * x + 19.0 * y);
}

struct FloorView {
  cv::Mat1b grey;
  cv::Mat1f disparity;  // the floor's exact disparity, invalid above the horizon
};

// What the reference camera sees of the textured floor from `pose` (world frame), brightness
// times `gain` plus `offset`.
FloorView viewFloor(const CameraRig& rig, const mrpt::poses::CPose2D& pose, double gain = 1.0, double offset = 0.0) {
  FloorView view{cv::Mat1b(rig.reference.height, rig.reference.width, uchar{0}),
                 cv::Mat1f(rig.reference.height, rig.reference.width, kInvalidDisparity)};
  for (int y = 0; y < view.grey.rows; ++y)
    for (int x = 0; x < view.grey.cols; ++x) {
      const auto on_robot = rig.floorPointOnRobot(x, y);
      if (!on_robot) continue;
      double world_x = 0.0, world_y = 0.0;
      pose.composePoint(on_robot->x, on_robot->y, world_x, world_y);
      view.grey(y, x) = cv::saturate_cast<uchar>(gain * floorTexture(world_x, world_y) + offset);
      mrpt::math::TPoint3D camera;
      rig.pose_on_robot.inverseComposePoint(mrpt::math::TPoint3D(on_robot->x, on_robot->y, 0.0), camera);
      view.disparity(y, x) = static_cast<float>(rig.disparityForDepth(camera.z));
    }
  return view;
}

// A robot driving over the textured floor, its floor odometry given every frame's view.
struct FloorDrive {
  const CameraRig& rig;
  FloorOdometry& odometry;
  mrpt::poses::CPose2D truth, wheels;
  FloorView view;

  // The view from where the robot is; stereo matches the floor unless `matched` is false.
  mrpt::poses::CPose2D look(bool matched = true) {
    view = viewFloor(rig, truth);
    if (!matched) view.disparity.setTo(kInvalidDisparity);
    return odometry.update(wheels, view.grey, view.disparity);
  }
  // Moves by `step`, the wheels reading `wheel_step`, and looks.
  mrpt::poses::CPose2D drive(const mrpt::poses::CPose2D& step, const mrpt::poses::CPose2D& wheel_step,
                             bool matched = true) {
    truth = truth + step;
    wheels = wheels + wheel_step;
    return look(matched);
  }
};

TEST(FloorMotionTest, FloorPixelsAreThoseWhoseDisparityIsTheFloorsAndLieWhereTheRaysMeetIt) {
  const CameraRig rig = floorRig();
  FloorView view = viewFloor(rig, mrpt::poses::CPose2D());
  // The lower-left quarter is a wall 1 m ahead: its disparity is the wall's, not the floor's.
  for (int y = 180; y < 240; ++y)
    for (int x = 0; x < 160; ++x) view.disparity(y, x) = static_cast<float>(rig.disparityForDepth(1.0));
  FloorMotionOptions options;
  options.pixel_step = 1;
  const FloorPixels floor = floorPixels(rig, smoothedForFloor(view.grey), view.disparity, options);
  ASSERT_GT(floor.on_robot.size(), 1000u);
  ASSERT_EQ(floor.on_robot.size(), floor.brightness.size());
  for (const cv::Point2d& point : floor.on_robot) {
    const double range = std::hypot(point.x, point.y);
    EXPECT_GE(range, options.min_range_m - 1e-9);
    EXPECT_LE(range, options.max_range_m + 1e-9);
  }
  // Exactly the pixels outside the wall that see the floor within the range limits.
  size_t expected = 0;
  for (int y = 0; y < 240; ++y)
    for (int x = 0; x < 320; ++x) {
      if (y >= 180 && x < 160) continue;
      const auto point = rig.floorPointOnRobot(x, y);
      if (!point) continue;
      const double range = std::hypot(point->x, point->y);
      if (range >= options.min_range_m && range <= options.max_range_m) ++expected;
    }
  EXPECT_EQ(floor.on_robot.size(), expected);
  // The image centre: the optical axis 30 degrees down from 0.5 m meets the floor 0.5 / tan(30)
  // ahead of the camera, which sits 0.1 m ahead of the robot's origin.
  const auto centre = rig.floorPointOnRobot(rig.reference.cx, rig.reference.cy);
  ASSERT_TRUE(centre.has_value());
  EXPECT_NEAR(centre->x, 0.1 + 0.5 / std::tan(mrpt::DEG2RAD(30.0)), 1e-9);
  EXPECT_NEAR(centre->y, 0.0, 1e-9);
}

TEST(FloorMotionTest, AlignmentRecoversAKnownMotionFromAWrongGuessAndAnExposureChange) {
  const CameraRig rig = floorRig();
  const mrpt::poses::CPose2D before(2.0, 1.0, 0.3);
  const mrpt::poses::CPose2D motion(0.08, 0.004, mrpt::DEG2RAD(4.0));
  const FloorView previous = viewFloor(rig, before);
  const FloorView current = viewFloor(rig, before + motion, 1.1, -8.0);
  const FloorPixels floor =
      floorPixels(rig, smoothedForFloor(current.grey), current.disparity, FloorMotionOptions());
  // The wheels' guess: 5% long, and turned 0.5 degrees too far.
  const mrpt::poses::CPose2D guess(0.084, 0.004, mrpt::DEG2RAD(4.5));
  const FloorAlignment alignment = alignFloor(rig, floor, smoothedForFloor(previous.grey), guess);
  ASSERT_TRUE(alignment.converged);
  EXPECT_GT(alignment.pixels, 1000);
  EXPECT_NEAR(alignment.motion.x(), motion.x(), 0.5e-3);
  EXPECT_NEAR(alignment.motion.y(), motion.y(), 0.5e-3);
  EXPECT_NEAR(mrpt::RAD2DEG(alignment.motion.phi()), 4.0, 0.02);
}

TEST(FloorMotionTest, OdometryFollowsTheFloorWhereTheWheelsReadLongAndKeepsThemWithoutFloor) {
  const CameraRig rig = floorRig();
  FloorMotionOptions options;
  options.enabled = true;
  FloorOdometry odometry(rig, options);
  // The robot drives an arc; the wheels read every step 4% long and turn 2% too far.
  const mrpt::poses::CPose2D step(0.06, 0.0, mrpt::DEG2RAD(3.0));
  const mrpt::poses::CPose2D wheel_step(0.0624, 0.0, mrpt::DEG2RAD(3.06));
  FloorDrive robot{rig, odometry, mrpt::poses::CPose2D(1.0, -0.5, 0.2), mrpt::poses::CPose2D(5.0, 5.0, 1.0), {}};
  mrpt::poses::CPose2D pose = robot.look();
  EXPECT_EQ(pose, robot.wheels);  // the first frame: the wheels' pose, the frame it is chained in
  mrpt::poses::CPose2D expected = robot.wheels;
  constexpr int kSteps = 40;
  for (int i = 0; i < kSteps; ++i) {
    expected = expected + step;
    pose = robot.drive(step, wheel_step);
  }
  EXPECT_EQ(odometry.measuredSteps(), kSteps);
  EXPECT_EQ(odometry.steps(), kSteps);
  EXPECT_NEAR(pose.x(), expected.x(), 2e-3);
  EXPECT_NEAR(pose.y(), expected.y(), 2e-3);
  EXPECT_NEAR(mrpt::RAD2DEG(mrpt::math::wrapToPi(pose.phi() - expected.phi())), 0.0, 0.05);
  // The wheels alone would be 10 cm and 2.4 degrees off by now.
  EXPECT_GT(std::hypot(robot.wheels.x() - expected.x(), robot.wheels.y() - expected.y()), 0.05);
  // What the floor measured of the wheels: 0.06 / 0.0624 of their distance, 3 / 3.06 of their turn.
  EXPECT_NEAR(odometry.distanceScale(), 0.06 / 0.0624, 2e-3);
  EXPECT_NEAR(odometry.turnScale(), 3.0 / 3.06, 2e-3);

  // Stereo matches nothing (a dark room): the step is the wheels', scaled as measured, which is
  // the true step.
  const mrpt::poses::CPose2D before = pose;
  pose = robot.drive(step, wheel_step, false);
  EXPECT_EQ(odometry.measuredSteps(), kSteps);
  const mrpt::poses::CPose2D kept = before + step;
  EXPECT_NEAR(pose.x(), kept.x(), 2e-4);
  EXPECT_NEAR(pose.y(), kept.y(), 2e-4);
  EXPECT_NEAR(mrpt::RAD2DEG(mrpt::math::wrapToPi(pose.phi() - kept.phi())), 0.0, 0.01);
}

TEST(FloorMotionTest, WithoutFloorFromTheStartOdometryIsTheWheels) {
  const CameraRig rig = floorRig();
  FloorMotionOptions options;
  options.enabled = true;
  options.wheel_turn_noise_per_rad = 0.01;
  options.wheel_heading_noise_deg_per_m = 0.14;
  FloorOdometry odometry(rig, options);
  const cv::Mat1b dark(rig.reference.height, rig.reference.width, uchar{0});
  const cv::Mat1f unmatched(rig.reference.height, rig.reference.width, kInvalidDisparity);
  const mrpt::poses::CPose2D step(0.1, 0.01, 0.05);
  mrpt::poses::CPose2D wheels(0.5, 0.2, -1.0);
  for (int i = 0; i < 20; ++i, wheels = wheels + step) {
    const mrpt::poses::CPose2D pose = odometry.update(wheels, dark, unmatched);
    EXPECT_NEAR(pose.x(), wheels.x(), 1e-9);
    EXPECT_NEAR(pose.y(), wheels.y(), 1e-9);
    EXPECT_NEAR(pose.phi(), wheels.phi(), 1e-9);
    if (i == 0) continue;
    // Each wheel step's doubt, by hand: its random part from 0.05 rad turned and 0.1 m driven,
    // sqrt((0.01 * 0.05)^2 + (0.14 deg * 0.1)^2) = 0.5565 mrad, and the unmeasured turn scale's
    // 0.05 * 0.05 rad.
    EXPECT_NEAR(odometry.lastTurnDoubt().sigma_rad, 0.5565e-3, 1e-7);
    EXPECT_NEAR(odometry.lastTurnDoubt().scale_sigma_rad, 2.5e-3, 1e-12);
  }
  EXPECT_EQ(odometry.measuredSteps(), 0);
  EXPECT_EQ(odometry.distanceScale(), 1.0);
  EXPECT_EQ(odometry.turnScale(), 1.0);
}

TEST(FloorMotionTest, TurnsWithoutFloorBeforeTheWheelsAreMeasuredAreCorrectedOnceTheyAre) {
  const CameraRig rig = floorRig();
  FloorMotionOptions options;
  options.enabled = true;
  options.wheel_turn_noise_per_rad = 0.01;
  FloorOdometry odometry(rig, options);
  // Turning on the spot, the wheels 2% large. The first three steps see no floor (facing a
  // wall): they are the wheels' own, with their doubt told to the localizer.
  const mrpt::poses::CPose2D step(0.0, 0.0, mrpt::DEG2RAD(10.0));
  const mrpt::poses::CPose2D wheel_step(0.0, 0.0, mrpt::DEG2RAD(10.2));
  const mrpt::poses::CPose2D start(1.0, 2.0, 0.5);
  FloorDrive robot{rig, odometry, start, start, {}};
  robot.look(false);
  for (int i = 0; i < 3; ++i) {
    robot.drive(step, wheel_step, false);
    EXPECT_NEAR(odometry.lastTurnDoubt().scale_sigma_rad, options.wheel_turn_scale_sigma * mrpt::DEG2RAD(10.2),
                1e-12);
    EXPECT_NEAR(odometry.lastTurnDoubt().sigma_rad, 0.01 * mrpt::DEG2RAD(10.2), 1e-12);
    EXPECT_FALSE(odometry.lastTurnDoubt().earlier_turns_scale);
  }
  EXPECT_EQ(odometry.measuredSteps(), 0);
  // Then the floor: once the turn scale is measured, the pose is the true one, the 0.6 degrees
  // the first three steps turned too far taken back, and the localizer is told their scale once.
  mrpt::poses::CPose2D pose;
  int scales_told = 0;
  for (int i = 0; i < 10; ++i) {
    pose = robot.drive(step, wheel_step);
    // A step the floor measured carries none of the wheels' doubt.
    EXPECT_EQ(odometry.lastTurnDoubt().sigma_rad, 0.0);
    EXPECT_EQ(odometry.lastTurnDoubt().scale_sigma_rad, 0.0);
    if (const auto scale = odometry.lastTurnDoubt().earlier_turns_scale) {
      ++scales_told;
      EXPECT_DOUBLE_EQ(*scale, odometry.turnScale());
    }
  }
  EXPECT_EQ(scales_told, 1);
  EXPECT_EQ(odometry.measuredSteps(), 10);
  EXPECT_NEAR(odometry.turnScale(), 1.0 / 1.02, 1e-3);
  EXPECT_NEAR(mrpt::RAD2DEG(mrpt::math::wrapToPi(pose.phi() - robot.truth.phi())), 0.0, 0.05);
  EXPECT_NEAR(pose.x(), robot.truth.x(), 1e-3);
  EXPECT_NEAR(pose.y(), robot.truth.y(), 1e-3);
}

TEST(FloorMotionTest, AnAlignmentFarFromTheWheelsIsRefused) {
  const CameraRig rig = floorRig();
  FloorMotionOptions options;
  options.enabled = true;
  FloorOdometry odometry(rig, options);
  // The floor does not move in the images (a camera frozen, or a floor moving with the robot),
  // while the wheels drive 3 cm: the floor's "standing still" is refused.
  const FloorView view = viewFloor(rig, mrpt::poses::CPose2D());
  odometry.update(mrpt::poses::CPose2D(), view.grey, view.disparity);
  const mrpt::poses::CPose2D pose = odometry.update(mrpt::poses::CPose2D(0.03, 0.0, 0.0), view.grey, view.disparity);
  EXPECT_EQ(odometry.measuredSteps(), 0);
  EXPECT_NEAR(pose.x(), 0.03, 1e-9);
}

}  // namespace
}  // namespace stereonav
