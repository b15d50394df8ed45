#include "observations/rig_observations.h"

#include <gtest/gtest.h>
#include <mrpt/poses/CPose3D.h>

#include "observations/external_images.h"
#include "sample_frames.h"

namespace stereonav {
namespace {

using mrpt::poses::CPose3D;

// A level rig at (0.2, 0.05, 0.8) looking along the robot's x axis: image x is the robot's -y
// and image y the robot's -z, so offsets are easy to work out by hand.
CameraRig levelRig(std::vector<SecondaryCamera> secondaries) {
  CameraRig rig = sampleRig(std::move(secondaries));
  rig.pose_on_robot = CameraRig::opticalPoseOnRobot(0.2, 0.05, 0.8, 0.0, 0.0);
  return rig;
}

void expectPosition(const CPose3D& pose, double x, double y, double z) {
  EXPECT_NEAR(pose.x(), x, 1e-9);
  EXPECT_NEAR(pose.y(), y, 1e-9);
  EXPECT_NEAR(pose.z(), z, 1e-9);
}

// Pixel of a robot-frame point in a camera with optical pose `pose` and intrinsics `camera`.
mrpt::math::TPoint2D project(const CPose3D& pose, const mrpt::img::TCamera& camera,
                             const mrpt::math::TPoint3D& point_on_robot) {
  const auto p = pose.inverseComposePoint(point_on_robot);
  return {camera.cx() + camera.fx() * p.x / p.z, camera.cy() + camera.fy() * p.y / p.z};
}

TEST(RigObservationsTest, TriclopsReferenceIsTheRightCameraOfThePair) {
  const RigFrame frame = sampleFrames(levelRig({{-1.0, 0.0}, {0.0, -1.0}}), 1)[0];
  const auto observations = toRigObservations(frame, "TRICLOPS");
  const auto& pair = *observations.pair;
  EXPECT_EQ(pair.sensorLabel, "TRICLOPS");
  EXPECT_TRUE(pair.hasImageRight);
  EXPECT_TRUE(samePixels(pair.imageRight.asCvMatRef(), frame.reference));
  EXPECT_TRUE(samePixels(pair.imageLeft.asCvMatRef(), frame.secondaries[0]));
  // The left camera is B = 0.1 m to the robot's left of the reference.
  expectPosition(CPose3D(pair.cameraPose), 0.2, 0.15, 0.8);
  expectPosition(CPose3D(pair.rightCameraPose), 0.1, 0.0, 0.0);
  EXPECT_DOUBLE_EQ(pair.leftCamera.fx(), 50.0);
  EXPECT_DOUBLE_EQ(pair.rightCamera.cy(), 23.5);
  EXPECT_EQ(pair.rightCamera.ncols, 64u);
  EXPECT_TRUE(pair.areImagesRectified());

  ASSERT_EQ(observations.extra_cameras.size(), 1u);
  const auto& top = *observations.extra_cameras[0];
  EXPECT_EQ(top.sensorLabel, "TRICLOPS_CAM2");
  EXPECT_EQ(top.timestamp, frame.timestamp);
  EXPECT_TRUE(samePixels(top.image.asCvMatRef(), frame.secondaries[1]));
  expectPosition(top.cameraPose, 0.2, 0.05, 0.9);  // B above the reference
  EXPECT_EQ(top.cameraParams.nrows, 48u);
}

TEST(RigObservationsTest, BinocularReferenceIsTheLeftCameraOfThePair) {
  const RigFrame frame = sampleFrames(levelRig({{1.0, 0.0}}), 1)[0];
  const auto observations = toRigObservations(frame, "BUMBLEBEE");
  const auto& pair = *observations.pair;
  EXPECT_TRUE(samePixels(pair.imageLeft.asCvMatRef(), frame.reference));
  EXPECT_TRUE(samePixels(pair.imageRight.asCvMatRef(), frame.secondaries[0]));
  expectPosition(CPose3D(pair.cameraPose), 0.2, 0.05, 0.8);
  expectPosition(CPose3D(pair.rightCameraPose), 0.1, 0.0, 0.0);
  EXPECT_TRUE(observations.extra_cameras.empty());
}

TEST(RigObservationsTest, MrptCameraPosesReproduceTheSecondaryCameraDisparityConvention) {
  // A point at depth Z has disparity d = f B / Z; secondary camera (bx, by) sees it at
  // (x - bx d, y - by d). Project through the MRPT poses to check the observation agrees.
  const CameraRig rig = triclopsRig();  // tilted and turned, so no axis is special
  const RigFrame frame = sampleFrames(rig, 1)[0];
  const auto observations = toRigObservations(frame, "TRICLOPS");
  const auto& pair = *observations.pair;
  const double depth = 2.5;
  const double d = rig.reference.focal_px * rig.baseline_m / depth;  // 2 px
  const auto point = rig.pose_on_robot.composePoint({0.3, -0.2, depth});
  const CPose3D left_pose(pair.cameraPose);
  const CPose3D right_pose = left_pose + CPose3D(pair.rightCameraPose);
  const auto in_reference = project(right_pose, pair.rightCamera, point);
  const auto in_left = project(left_pose, pair.leftCamera, point);
  const auto in_top = project(observations.extra_cameras[0]->cameraPose,
                              observations.extra_cameras[0]->cameraParams, point);
  EXPECT_NEAR(in_left.x, in_reference.x + d, 1e-9);  // bx = -1
  EXPECT_NEAR(in_left.y, in_reference.y, 1e-9);
  EXPECT_NEAR(in_top.x, in_reference.x, 1e-9);
  EXPECT_NEAR(in_top.y, in_reference.y + d, 1e-9);  // by = -1
}

TEST(RigObservationsTest, FirstSecondaryMustBeBesideTheReference) {
  RigFrame frame = sampleFrames(sampleRig({{0.0, -1.0}, {-1.0, 0.0}}), 1)[0];
  EXPECT_THROW(toRigObservations(frame, "TRICLOPS"), std::invalid_argument);
}

TEST(RigObservationsTest, ConvertsBackToTheSameFrame) {
  for (const auto& rig : {triclopsRig(), binocularRig()}) {
    RigFrame frame = sampleFrames(rig, 1)[0];
    frame.odometry.reset();  // odometry travels in its own observation
    const auto observations = toRigObservations(frame, "TRICLOPS");
    FrameRectifier rectifier;
    expectSameFrame(frame, fromRigObservations(*observations.pair, observations.extra_cameras, "",
                                               PairReference::kLeft, rectifier));
  }
}

TEST(RigObservationsTest, UnnamedPairTakesTheReferenceSideFromTheCaller) {
  const RigFrame frame = sampleFrames(triclopsRig(), 1)[0];
  auto observations = toRigObservations(frame, "TRICLOPS");
  observations.pair->leftCamera.cameraName = "left";
  observations.pair->rightCamera.cameraName = "right";
  FrameRectifier rectifier;
  const RigFrame as_right =
      fromRigObservations(*observations.pair, {}, "", PairReference::kRight, rectifier);
  EXPECT_DOUBLE_EQ(as_right.rig.secondaries[0].bx, -1.0);
  EXPECT_TRUE(samePixels(as_right.reference, frame.reference));
  const RigFrame as_left =
      fromRigObservations(*observations.pair, {}, "", PairReference::kLeft, rectifier);
  EXPECT_DOUBLE_EQ(as_left.rig.secondaries[0].bx, 1.0);
  EXPECT_TRUE(samePixels(as_left.reference, frame.secondaries[0]));
}

RejectReason rejectionOf(const RigObservations& observations, const std::string& images = "") {
  try {
    FrameRectifier rectifier;
    fromRigObservations(*observations.pair, observations.extra_cameras, images,
                        PairReference::kLeft, rectifier);
  } catch (const ObservationRejected& rejection) {
    return rejection.reason();
  }
  ADD_FAILURE() << "not rejected";
  return RejectReason::kWrongCameraCount;
}

TEST(RigObservationsTest, RectifiesACameraTurnedAboutItsOpticalAxis) {
  // The top camera rolled by 0.05 rad: the centres still span the reference's image plane and
  // the roll leaves every camera's centre ray where it was, so the rectified rig is the original
  // one, the reference image is resampled through an identity map, and only the top image turns.
  const RigFrame frame = sampleFrames(triclopsRig(), 1)[0];
  auto observations = toRigObservations(frame, "TRICLOPS");
  auto& top = *observations.extra_cameras[0];
  top.cameraPose = top.cameraPose + CPose3D(0, 0, 0, 0.05, 0, 0);
  FrameRectifier rectifier;
  const RigFrame rectified = fromRigObservations(*observations.pair, observations.extra_cameras,
                                                 "", PairReference::kLeft, rectifier);
  ASSERT_EQ(rectified.rig.secondaries.size(), 2u);
  EXPECT_NEAR(rectified.rig.reference.focal_px, frame.rig.reference.focal_px, 1e-9);
  EXPECT_NEAR(rectified.rig.reference.cx, frame.rig.reference.cx, 1e-6);
  EXPECT_NEAR(rectified.rig.reference.cy, frame.rig.reference.cy, 1e-6);
  EXPECT_NEAR(rectified.rig.secondaries[0].bx, -1.0, 1e-6);
  EXPECT_NEAR(rectified.rig.secondaries[0].by, 0.0, 1e-6);
  EXPECT_NEAR(rectified.rig.secondaries[1].bx, 0.0, 1e-6);
  EXPECT_NEAR(rectified.rig.secondaries[1].by, -1.0, 1e-6);
  EXPECT_TRUE(rectified.rig.pose_on_robot.distanceTo(frame.rig.pose_on_robot) < 1e-6);
  EXPECT_TRUE(samePixels(rectified.reference, frame.reference));
  EXPECT_FALSE(samePixels(rectified.secondaries[1], frame.secondaries[1]));
}

TEST(RigObservationsTest, RejectsWhatIsNotARectifiedRigWithImagesOfItsSize) {
  const RigFrame frame = sampleFrames(triclopsRig(), 1)[0];
  const auto fresh = [&] { return toRigObservations(frame, "TRICLOPS"); };

  auto uncalibrated = fresh();
  uncalibrated.pair->rightCamera.intrinsicParams.setZero();
  EXPECT_EQ(rejectionOf(uncalibrated), RejectReason::kMissingCalibration);

  auto zero_baseline = fresh();
  zero_baseline.pair->rightCameraPose = mrpt::poses::CPose3DQuat();
  EXPECT_EQ(rejectionOf(zero_baseline), RejectReason::kMissingCalibration);

  auto fisheye = fresh();
  fisheye.pair->leftCamera.setDistortionKannalaBrandt(0.1, 0.01, 0, 0);
  EXPECT_EQ(rejectionOf(fisheye), RejectReason::kNotRectified);

  auto looking_sideways = fresh();  // no common image plane sees what it sees
  looking_sideways.extra_cameras[0]->cameraPose =
      looking_sideways.extra_cameras[0]->cameraPose + CPose3D(0, 0, 0, 0, 1.2, 0);
  EXPECT_EQ(rejectionOf(looking_sideways), RejectReason::kNotRectified);

  // The top camera moved onto the horizontal baseline: rectified as it is (a collinear rig),
  // but with lens distortion no plane through the centres is defined to rectify it onto.
  auto collinear = fresh();
  collinear.extra_cameras[0]->cameraPose = CPose3D(collinear.pair->cameraPose) +
                                           CPose3D(-0.1, 0, 0, 0, 0, 0);
  collinear.pair->leftCamera.setDistortionPlumbBob(-0.2, 0.05, 0, 0);
  EXPECT_EQ(rejectionOf(collinear), RejectReason::kNotRectified);

  auto small_image = fresh();
  small_image.pair->imageLeft =
      mrpt::img::CImage(cv::Mat(48, 32, CV_8UC1, cv::Scalar(7)), mrpt::img::DEEP_COPY);
  EXPECT_EQ(rejectionOf(small_image), RejectReason::kWrongImageFormat);

  auto colour_among_grey = fresh();
  colour_among_grey.extra_cameras[0]->image =
      mrpt::img::CImage(cv::Mat(48, 64, CV_8UC3, cv::Scalar(7, 7, 7)), mrpt::img::DEEP_COPY);
  EXPECT_EQ(rejectionOf(colour_among_grey), RejectReason::kWrongImageFormat);

  auto lost_file = fresh();
  lost_file.pair->imageLeft.setExternalStorage("nowhere.png");
  EXPECT_EQ(rejectionOf(lost_file, "/nonexistent"), RejectReason::kMissingImage);
}

}  // namespace
}  // namespace stereonav
