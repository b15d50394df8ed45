#include "ros_bridge/ros_frame_assembler.h"

#include <boost/make_shared.hpp>
#include <gtest/gtest.h>
#include <mrpt/ros1bridge/time.h>

#include "ros_bridge/ros_camera_messages.h"
#include "../observations/sample_frames.h"

namespace stereonav {
namespace {

struct Messages {
  std::vector<RosCameraMessage> cameras;
  mrpt::system::TTimeStamp stamp;
};

std::vector<Messages> binocularMessages(size_t count) {
  std::vector<Messages> all;
  for (const RigFrame& frame : sampleFrames(binocularRig(), count)) {
    all.push_back({toRosCameraMessages(frame, "head"), frame.timestamp});
  }
  return all;
}

RosHeadOptions binocularHead(bool wait_for_odometry) {
  RosHeadOptions head;
  head.wait_for_odometry = wait_for_odometry;
  return head;
}

void add(RosFrameAssembler& assembler, const Messages& messages, bool infos_first) {
  for (size_t camera = 0; camera < messages.cameras.size(); ++camera) {
    const auto image = boost::make_shared<sensor_msgs::Image>(messages.cameras[camera].image);
    const auto info = boost::make_shared<sensor_msgs::CameraInfo>(messages.cameras[camera].info);
    if (infos_first) assembler.addCameraInfo(camera, info);
    assembler.addImage(camera, image);
    if (!infos_first) assembler.addCameraInfo(camera, info);
  }
}

TEST(RosFrameAssemblerTest, FramesWaitForTheOdometryOfTheirInstant) {
  const auto messages = binocularMessages(2);
  RosFrameAssembler assembler(binocularHead(true));
  add(assembler, messages[0], false);
  EXPECT_FALSE(assembler.next());  // no odometry at or after the capture yet
  EXPECT_EQ(assembler.waiting(), 1u);
  assembler.addOdometry(messages[0].stamp - std::chrono::milliseconds(100), {0.0, 0.0, 0.0});
  EXPECT_FALSE(assembler.next());
  assembler.addOdometry(messages[0].stamp + std::chrono::milliseconds(50), {0.15, 0.0, 0.0});
  const auto frame = assembler.next();
  ASSERT_TRUE(frame);
  ASSERT_TRUE(frame->odometry);
  EXPECT_NEAR(frame->odometry->x(), 0.1, 1e-4);  // 1 m/s from -0.1 s to 0.05 s, at 0 s
  // At the end, a frame past the last reading takes the newest.
  add(assembler, messages[1], true);
  EXPECT_FALSE(assembler.next());
  assembler.finish();
  const auto last = assembler.next();
  ASSERT_TRUE(last);
  EXPECT_DOUBLE_EQ(last->odometry->x(), 0.15);
}

TEST(RosFrameAssemblerTest, AMissingPartnerIsSkippedAndCountedNeverACrash) {
  const auto messages = binocularMessages(3);
  RosFrameAssembler assembler(binocularHead(false));
  add(assembler, messages[0], false);
  // The second capture loses its right image in transit.
  assembler.addImage(0, boost::make_shared<sensor_msgs::Image>(messages[1].cameras[0].image));
  assembler.addCameraInfo(0, boost::make_shared<sensor_msgs::CameraInfo>(messages[1].cameras[0].info));
  add(assembler, messages[2], false);
  assembler.finish();
  std::vector<mrpt::system::TTimeStamp> stamps;
  while (auto frame = assembler.next()) stamps.push_back(frame->timestamp);
  EXPECT_EQ(stamps, (std::vector<mrpt::system::TTimeStamp>{messages[0].stamp, messages[2].stamp}));
  EXPECT_EQ(assembler.skipped().count[static_cast<size_t>(RejectReason::kMissingPartner)], 1u);
  EXPECT_EQ(assembler.skipped().total(), 1u);
}

TEST(RosFrameAssemblerTest, UnusableMessagesAreCountedWithTheirReason) {
  auto messages = binocularMessages(1)[0];
  messages.cameras[1].image.encoding = "32FC1";
  RosFrameAssembler assembler(binocularHead(false));
  add(assembler, messages, false);
  assembler.finish();
  EXPECT_FALSE(assembler.next());
  EXPECT_EQ(assembler.skipped().count[static_cast<size_t>(RejectReason::kWrongImageFormat)], 1u);
  EXPECT_NE(assembler.skipped().summary().find("32FC1"), std::string::npos);
}

TEST(RosFrameAssemblerTest, HeadOfTheIniFollowsItsRig) {
  MappingOptions options;
  EXPECT_EQ(rosHeadOptions(options).cameras, 2u);
  EXPECT_FALSE(rosHeadOptions(options).reference_is_right);
  options.rig = triclopsRig();
  options.pairing.max_time_difference_s = 0.02;
  const RosHeadOptions head = rosHeadOptions(options);
  EXPECT_EQ(head.cameras, 3u);
  EXPECT_TRUE(head.reference_is_right);
  EXPECT_DOUBLE_EQ(head.max_time_difference_s, 0.02);
  EXPECT_DOUBLE_EQ(head.mount.z(), triclopsRig().pose_on_robot.z());
}

}  // namespace
}  // namespace stereonav
