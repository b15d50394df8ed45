#include "ros_bridge/ros_camera_messages.h"

#include <boost/make_shared.hpp>
#include <gtest/gtest.h>
#include <mrpt/core/bits_math.h>
#include <cv_bridge/cv_bridge.h>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>
#include <sensor_msgs/image_encodings.h>

#include "observations/frame_rectifier.h"
#include "observations/rig_observations.h"
#include "ros_bridge/ros_frame_assembler.h"
#include "../observations/sample_frames.h"
#include "../rectification/synthetic_heads.h"

namespace stereonav {
namespace {

// The frame back from its messages, through the path the node and the bag reader take.
RigFrame throughMessages(const RigFrame& frame, bool reference_is_right) {
  const std::vector<RosCameraMessage> messages = toRosCameraMessages(frame, "head");
  RosHeadOptions head;
  head.cameras = messages.size();
  head.reference_is_right = reference_is_right;
  head.mount = frame.rig.pose_on_robot;
  head.wait_for_odometry = false;
  RosFrameAssembler assembler(head);
  for (size_t camera = 0; camera < messages.size(); ++camera) {
    assembler.addImage(camera, boost::make_shared<sensor_msgs::Image>(messages[camera].image));
    assembler.addCameraInfo(camera, boost::make_shared<sensor_msgs::CameraInfo>(messages[camera].info));
  }
  auto back = assembler.next();
  EXPECT_TRUE(back) << assembler.skipped().summary();
  return back ? *back : RigFrame{};
}

void expectSameCapture(const RigFrame& expected, const RigFrame& actual) {
  EXPECT_EQ(actual.timestamp, expected.timestamp);
  EXPECT_EQ(actual.rig.reference.width, expected.rig.reference.width);
  EXPECT_DOUBLE_EQ(actual.rig.reference.focal_px, expected.rig.reference.focal_px);
  EXPECT_DOUBLE_EQ(actual.rig.reference.cx, expected.rig.reference.cx);
  EXPECT_DOUBLE_EQ(actual.rig.reference.cy, expected.rig.reference.cy);
  EXPECT_NEAR(actual.rig.baseline_m, expected.rig.baseline_m, 1e-12);
  ASSERT_EQ(actual.rig.secondaries.size(), expected.rig.secondaries.size());
  for (size_t k = 0; k < expected.rig.secondaries.size(); ++k) {
    EXPECT_NEAR(actual.rig.secondaries[k].bx, expected.rig.secondaries[k].bx, 1e-9) << k;
    EXPECT_NEAR(actual.rig.secondaries[k].by, expected.rig.secondaries[k].by, 1e-9) << k;
  }
  EXPECT_EQ(cv::norm(actual.reference, expected.reference, cv::NORM_INF), 0.0);
  for (size_t k = 0; k < expected.secondaries.size(); ++k) {
    EXPECT_EQ(cv::norm(actual.secondaries[k], expected.secondaries[k], cv::NORM_INF), 0.0) << k;
  }
}

TEST(RosCameraMessagesTest, TriclopsTravelsAsLeftRightTopWithStereoImageProcProjections) {
  const RigFrame frame = sampleFrames(triclopsRig(), 1)[0];
  const std::vector<RosCameraMessage> messages = toRosCameraMessages(frame, "head");
  ASSERT_EQ(messages.size(), 3u);
  // Reference = right camera; the left one is its secondary at bx = -1, the top one at by = -1.
  // P's Tx, Ty = -f X, -f Y with (X, Y) the centre in the left camera's frame: right at
  // (B, 0), top above the right one at (B, -B). By hand: f = 50, B = 0.1.
  EXPECT_DOUBLE_EQ(messages[0].info.P[3], 0.0);
  EXPECT_DOUBLE_EQ(messages[1].info.P[3], -5.0);
  EXPECT_DOUBLE_EQ(messages[1].info.P[7], 0.0);
  EXPECT_DOUBLE_EQ(messages[2].info.P[3], -5.0);
  EXPECT_DOUBLE_EQ(messages[2].info.P[7], 5.0);
  EXPECT_EQ(messages[0].image.encoding, sensor_msgs::image_encodings::MONO8);
  EXPECT_EQ(messages[1].info.header.frame_id, "head_right_optical");
  // The right image is the reference's pixels, the left image the first secondary's.
  EXPECT_EQ(messages[1].image.data[0], frame.reference.at<uint8_t>(0, 0));
  EXPECT_EQ(messages[0].image.data[0], frame.secondaries[0].at<uint8_t>(0, 0));
  expectSameCapture(frame, throughMessages(frame, true));
}

TEST(RosCameraMessagesTest, BinocularColourHeadComesBackPixelForPixel) {
  const RigFrame frame = sampleFrames(binocularRig(), 1, CV_8UC3)[0];
  const std::vector<RosCameraMessage> messages = toRosCameraMessages(frame, "head");
  ASSERT_EQ(messages.size(), 2u);
  EXPECT_EQ(messages[0].image.encoding, sensor_msgs::image_encodings::BGR8);
  expectSameCapture(frame, throughMessages(frame, false));
}

TEST(RosCameraMessagesTest, CameraPoseComesFromRAndP) {
  sensor_msgs::CameraInfo info;
  info.width = 64;
  info.height = 48;
  info.K = {50, 0, 31.5, 0, 50, 23.5, 0, 0, 1};
  // Turned 10 degrees about the optical y axis into the rectified frame, 0.12 m right of the
  // left camera.
  const double a = mrpt::DEG2RAD(10.0);
  info.R = {std::cos(a), 0, std::sin(a), 0, 1, 0, -std::sin(a), 0, std::cos(a)};
  info.P = {60, 0, 32, -60 * 0.12, 0, 60, 24, 0, 0, 0, 1, 0};
  info.distortion_model = "plumb_bob";
  info.D = {-0.1, 0.02, 0.001, -0.002, 0.003};
  sensor_msgs::Image image;
  image.width = 64;
  image.height = 48;
  image.encoding = sensor_msgs::image_encodings::MONO8;
  image.step = 64;
  image.data.assign(64 * 48, 7);
  const auto observation = toCameraObservation(image, info, "right");
  EXPECT_NEAR(observation->cameraPose.x(), 0.12, 1e-12);
  EXPECT_NEAR(observation->cameraPose.y(), 0.0, 1e-12);
  // The camera's optical axis, in the rectified frame, is R's third column (R takes camera
  // coordinates to rectified ones).
  const mrpt::math::TVector3D axis = observation->cameraPose.rotateVector({0, 0, 1});
  EXPECT_NEAR(axis.x, std::sin(a), 1e-12);
  EXPECT_NEAR(axis.z, std::cos(a), 1e-12);
  EXPECT_DOUBLE_EQ(observation->cameraParams.fx(), 50.0);
  EXPECT_EQ(observation->cameraParams.distortion, mrpt::img::DistortionModel::plumb_bob);
  EXPECT_DOUBLE_EQ(observation->cameraParams.dist[3], -0.002);

  info.width = 32;
  EXPECT_THROW(toCameraObservation(image, info, "right"), ObservationRejected);
  info.width = 64;
  info.distortion_model = "equidistant";
  EXPECT_THROW(toCameraObservation(image, info, "right"), ObservationRejected);
  info.distortion_model = "plumb_bob";
  image.encoding = "32FC1";
  EXPECT_THROW(toCameraObservation(image, info, "right"), ObservationRejected);
}

// A raw head as a ROS driver publishes it (image_raw, with K, D and OpenCV's stereoRectify R and
// P in its CameraInfo): a dot drawn where a scene point falls in each raw image comes out of the
// assembler on one row, at the disparity of its depth.
TEST(RosCameraMessagesTest, RawHeadIsRectifiedFromItsCameraInfo) {
  const RigCalibration head = rawBinocularHead();
  const CameraCalibration& left = head.cameras[0];
  const CameraCalibration& right = head.cameras[1];
  cv::Mat r1, r2, p1, p2, q;
  cv::stereoRectify(left.camera_matrix, left.distortion, right.camera_matrix, right.distortion,
                    left.size, right.rotation, right.translation, r1, r2, p1, p2, q,
                    cv::CALIB_ZERO_DISPARITY, 0.0);
  const cv::Vec3d point(-0.3, 0.4, 2.5);  // in the left camera's frame
  RosHeadOptions options;
  options.wait_for_odometry = false;
  RosFrameAssembler assembler(options);
  const std::vector<std::pair<const CameraCalibration*, std::pair<cv::Mat, cv::Mat>>> cameras{
      {&left, {r1, p1}}, {&right, {r2, p2}}};
  for (size_t k = 0; k < cameras.size(); ++k) {
    const CameraCalibration& camera = *cameras[k].first;
    cv::Mat image(camera.size, CV_8UC1, cv::Scalar(0));
    const cv::Point2f centre = projectRaw(camera, point);
    cv::circle(image, cv::Point(cvRound(centre.x * 16), cvRound(centre.y * 16)), 4 * 16,
               cv::Scalar(255), cv::FILLED, cv::LINE_AA, 4);
    std_msgs::Header header;
    header.stamp = ros::Time(100, 0);
    auto info = boost::make_shared<sensor_msgs::CameraInfo>();
    info->header = header;
    info->width = static_cast<uint32_t>(camera.size.width);
    info->height = static_cast<uint32_t>(camera.size.height);
    info->distortion_model = "plumb_bob";
    info->D = camera.distortion;
    for (int i = 0; i < 9; ++i) info->K[i] = camera.camera_matrix.val[i];
    for (int i = 0; i < 9; ++i) info->R[i] = cameras[k].second.first.at<double>(i / 3, i % 3);
    for (int i = 0; i < 12; ++i) info->P[i] = cameras[k].second.second.at<double>(i / 4, i % 4);
    assembler.addImage(k, cv_bridge::CvImage(header, "mono8", image).toImageMsg());
    assembler.addCameraInfo(k, info);
  }
  const auto frame = assembler.next();
  ASSERT_TRUE(frame) << assembler.skipped().summary();
  EXPECT_NEAR(frame->rig.baseline_m, cv::norm(right.translation), 1e-6);
  std::vector<cv::Point2d> dots;
  for (const cv::Mat* image : {&frame->reference, &frame->secondaries[0]}) {
    const cv::Moments m = cv::moments(*image);
    ASSERT_GT(m.m00, 0.0);
    dots.push_back({m.m10 / m.m00, m.m01 / m.m00});
  }
  EXPECT_NEAR(dots[0].y, dots[1].y, 0.1);
  // Depth from the rectified disparity: the point's distance along the rectified optical axis.
  EXPECT_NEAR(frame->rig.depthForDisparity(dots[0].x - dots[1].x), 2.5, 0.05);
}

TEST(RosCameraMessagesTest, ARigTheConventionCannotCarryIsRefused) {
  RigFrame frame = sampleFrames(sampleRig({{0.0, -1.0}}), 1)[0];  // secondary above: no pair
  EXPECT_THROW(toRosCameraMessages(frame, "head"), std::invalid_argument);
}

}  // namespace
}  // namespace stereonav
