#pragma once

#include <functional>
#include <string>

#include "observations/rawlog_reader.h"
#include "observations/rawlog_writer.h"
#include "ros_bridge/ros_frame_assembler.h"

namespace stereonav {

// The topics of a stereo head in a bag, as stereo_image_proc names them under the head's
// namespace: <ns>/<camera>/image_rect (or image_raw) and <ns>/<camera>/camera_info for camera
// left, right and top (kRosCameraNames); odometry as nav_msgs/Odometry.
constexpr const char* kRosStereoNamespace = "/stereo";
constexpr const char* kRosOdometryTopic = "/odom";

// Writes `bag_path` from a rawlog read as `stereonav map` reads it: every frame as its cameras'
// Image + CameraInfo on /stereo/<camera>/image_rect and /stereo/<camera>/camera_info
// (ros_camera_messages.h) and, when the frame has odometry, a nav_msgs/Odometry on /odom (frame
// "odom", child "base_link"), all stamped and recorded at the frame's instant. The bag is written
// beside its path and renamed into place when complete. Returns the number of frames written;
// throws std::runtime_error naming the file that cannot be read or written.
size_t writeRosbagFromRawlog(const std::string& rawlog_path, const RawlogReaderOptions& reader,
                             const std::string& bag_path,
                             const std::function<void(size_t frames)>& progress = {});

struct RosbagConversionReport {
  size_t frames = 0;
  size_t odometry_messages = 0;
  std::string image_topics;  // the topics read, e.g. "/stereo/left/image_rect /stereo/right/..."
  SkippedFrames skipped;
  std::string damage;  // "" unless the bag stopped being readable part way
};

// Reads a bag of a stereo head (topics found by their names, whatever their namespace, rectified
// images preferred over raw; the first nav_msgs/Odometry topic as odometry) in time order and
// writes its frames, each with the odometry pose of its instant, through `writer`. Throws
// std::runtime_error naming the bag if it cannot be read or has no topics of the head's cameras.
RosbagConversionReport convertRosbagToRawlog(const std::string& bag_path, const RosHeadOptions& head,
                                             RawlogWriter& writer,
                                             const std::function<void(size_t frames)>& progress = {});

}  // namespace stereonav
