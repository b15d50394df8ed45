#pragma once

#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPose3D.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>

#include <deque>
#include <optional>
#include <string>
#include <vector>

#include "mapping/mapping_options.h"
#include "observations/camera_image_pairing.h"
#include "observations/frame_rectifier.h"
#include "observations/rawlog_reader.h"
#include "ros_bridge/odometry_history.h"

namespace stereonav {

// The head as it arrives over ROS (ros_camera_messages.h) and what to make of it.
struct RosHeadOptions {
  size_t cameras = 2;               // 2: left and right; 3: and top
  bool reference_is_right = false;  // which camera of the pair is the rig's reference
  double max_time_difference_s = 0.005;  // between the cameras of one capture
  // The reference camera's optical frame on the robot (CameraRig::pose_on_robot).
  mrpt::poses::CPose3D mount = CameraRig{}.pose_on_robot;
  // Frames wait until odometry has a reading at or after their instant, and take the pose
  // interpolated there; false: frames go out as soon as they are paired, without odometry.
  bool wait_for_odometry = true;
};

// The head of a mapping ini: 1 + the [rig]'s secondary cameras, the reference on the right when
// its first secondary sits at bx < 0 (the Triclops), the [rig] mount and [rawlog]
// pairing_tolerance_s. Without a [rig]: a binocular head referenced on its left camera, mounted
// where CameraRig's defaults say.
RosHeadOptions rosHeadOptions(const MappingOptions& options);

// Turns the camera and odometry messages of a live head or a bag into RigFrames, the way
// RawlogReader does for a rawlog: cameras paired by time (CameraImagePairer), calibrated from
// their CameraInfo and rectified if they are not (FrameRectifier), each frame given the odometry
// pose of its own instant. Frames come out in time order.
class RosFrameAssembler {
 public:
  // Throws std::invalid_argument for a head of other than 2 or 3 cameras.
  explicit RosFrameAssembler(const RosHeadOptions& options);

  // `camera` indexes kRosCameraNames; a message of a camera the head does not have is ignored.
  // An image goes with the CameraInfo of the same stamp, whichever arrives first. Messages that
  // cannot be used are counted in skipped(), never thrown.
  void addImage(size_t camera, const sensor_msgs::Image::ConstPtr& image);
  void addCameraInfo(size_t camera, const sensor_msgs::CameraInfo::ConstPtr& info);
  void addOdometry(mrpt::system::TTimeStamp stamp, const mrpt::poses::CPose2D& pose);
  // No more messages: pending captures are decided, and frames still waiting for a later odometry
  // reading take the newest one.
  void finish();

  // The next frame that is ready, oldest first.
  std::optional<RigFrame> next();

  size_t cameras() const { return options_.cameras; }
  const SkippedFrames& skipped() const { return skipped_; }
  // Frames paired and waiting for their odometry.
  size_t waiting() const { return frames_.size(); }

 private:
  // Pairs camera `camera`'s queued images and CameraInfos of equal stamps.
  void matchCameraMessages(size_t camera);
  void convertDecidedCaptures();

  RosHeadOptions options_;
  std::vector<std::string> labels_;  // kRosCameraNames in rig order, reference first
  // Per camera, messages whose partner (image or CameraInfo) has not arrived yet.
  std::vector<std::deque<sensor_msgs::Image::ConstPtr>> images_;
  std::vector<std::deque<sensor_msgs::CameraInfo::ConstPtr>> infos_;
  CameraImagePairer pairer_;
  FrameRectifier rectifier_;
  OdometryHistory odometry_;
  std::deque<RigFrame> frames_;
  bool finished_ = false;
  SkippedFrames skipped_;
};

}  // namespace stereonav
