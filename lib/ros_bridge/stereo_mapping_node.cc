#include "ros_bridge/stereo_mapping_node.h"

#include <cv_bridge/cv_bridge.h>
#include <mrpt/ros1bridge/laser_scan.h>
#include <mrpt/ros1bridge/map.h>
#include <mrpt/ros1bridge/pose.h>
#include <mrpt/ros1bridge/time.h>
#include <nav_msgs/OccupancyGrid.h>
#include <sensor_msgs/LaserScan.h>
#include <sensor_msgs/image_encodings.h>
#include <std_msgs/UInt32.h>

#include <algorithm>
#include <chrono>
#include <sstream>
#include <stdexcept>

#include "mapping/map_outputs.h"
#include "occupancy_grid/grid_conversion.h"
#include "ros_bridge/ros_camera_messages.h"

namespace stereonav {
namespace {

// A capture whose odometry tf has not told for this long, both after a later capture's stamp and
// by the clock, is given up. By the stamps alone a bag played faster than real time (rosbag play
// -r 6) waited a sixth of a second, less than tf, on its own thread, sometimes took under load.
constexpr double kMaxTfWaitS = 1.0;

RosHeadOptions headOptions(const MappingOptions& mapping, const MappingNodeOptions& options) {
  RosHeadOptions head = rosHeadOptions(mapping);
  head.wait_for_odometry = options.odometry_source == "topic";
  return head;
}

}  // namespace

MappingNodeOptions loadMappingNodeOptions(const ros::NodeHandle& private_node) {
  MappingNodeOptions options;
  private_node.param("odometry_source", options.odometry_source, options.odometry_source);
  private_node.param("odom_frame", options.odom_frame, options.odom_frame);
  private_node.param("base_frame", options.base_frame, options.base_frame);
  private_node.param("map_every_frames", options.map_every_frames, options.map_every_frames);
  if (options.odometry_source != "topic" && options.odometry_source != "tf") {
    throw std::invalid_argument("~odometry_source '" + options.odometry_source +
                                "': expected topic or tf");
  }
  if (options.map_every_frames < 1) {
    throw std::invalid_argument("~map_every_frames " + std::to_string(options.map_every_frames) +
                                ": expected 1 or more");
  }
  return options;
}

StereoMappingNode::StereoMappingNode(ros::NodeHandle& node, const MappingOptions& mapping,
                                     const MappingNodeOptions& options)
    : mapping_(mapping), options_(options), assembler_(headOptions(mapping, options)) {
  // The stereo scan is published every frame, so the mapper makes it whatever the grid model.
  mapping_.mapper.virtual_scans = true;
  constexpr uint32_t kQueue = 100;  // a burst of captures waits rather than being dropped
  for (size_t camera = 0; camera < assembler_.cameras(); ++camera) {
    const std::string prefix = std::string("stereo/") + kRosCameraNames[camera];
    subscribers_.push_back(node.subscribe<sensor_msgs::Image>(
        prefix + "/image_rect", kQueue, [this, camera](const sensor_msgs::Image::ConstPtr& image) {
          assembler_.addImage(camera, image);
          mapReadyFrames();
        }));
    subscribers_.push_back(node.subscribe<sensor_msgs::CameraInfo>(
        prefix + "/camera_info", kQueue,
        [this, camera](const sensor_msgs::CameraInfo::ConstPtr& info) {
          assembler_.addCameraInfo(camera, info);
          mapReadyFrames();
        }));
  }
  if (options_.odometry_source == "topic") {
    subscribers_.push_back(node.subscribe("odom", kQueue, &StereoMappingNode::onOdometry, this));
  } else {
    tf_buffer_ = std::make_unique<tf2_ros::Buffer>();
    tf_listener_ = std::make_unique<tf2_ros::TransformListener>(*tf_buffer_);
    // tf arrives on its own thread: captures waiting for it are looked at again on a timer too.
    tf_timer_ = node.createTimer(ros::Duration(0.02), [this](const ros::TimerEvent&) { mapReadyFrames(); });
  }
  map_publisher_ = node.advertise<nav_msgs::OccupancyGrid>("map", 1, true);
  scan_publisher_ = node.advertise<sensor_msgs::LaserScan>("stereo_scan", 10);
  panel_publisher_ = node.advertise<sensor_msgs::Image>("debug_panel", 2);
  frames_publisher_ = node.advertise<std_msgs::UInt32>("frames_mapped", 1, true);
}

void StereoMappingNode::onOdometry(const nav_msgs::Odometry::ConstPtr& odometry) {
  assembler_.addOdometry(mrpt::ros1bridge::fromROS(odometry->header.stamp),
                         mrpt::poses::CPose2D(mrpt::ros1bridge::fromROS(odometry->pose.pose)));
  mapReadyFrames();
}

bool StereoMappingNode::odometryFromTf(RigFrame& frame) {
  const ros::Time stamp = mrpt::ros1bridge::toROS(frame.timestamp);
  std::string error;
  if (!tf_buffer_->canTransform(options_.odom_frame, options_.base_frame, stamp, &error)) return false;
  const geometry_msgs::TransformStamped transform =
      tf_buffer_->lookupTransform(options_.odom_frame, options_.base_frame, stamp);
  geometry_msgs::Pose pose;
  pose.position.x = transform.transform.translation.x;
  pose.position.y = transform.transform.translation.y;
  pose.position.z = transform.transform.translation.z;
  pose.orientation = transform.transform.rotation;
  frame.odometry = mrpt::poses::CPose2D(mrpt::ros1bridge::fromROS(pose));
  return true;
}

void StereoMappingNode::mapReadyFrames() {
  while (auto frame = assembler_.next()) {
    if (!tf_buffer_) {
      map(*frame);
      continue;
    }
    waiting_for_tf_.push_back({std::move(*frame), std::chrono::steady_clock::now()});
  }
  while (!waiting_for_tf_.empty()) {
    RigFrame& oldest = waiting_for_tf_.front().frame;
    if (!odometryFromTf(oldest)) {
      const double waited = mrpt::system::timeDifference(oldest.timestamp, waiting_for_tf_.back().frame.timestamp);
      const double waited_by_clock =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - waiting_for_tf_.front().arrived).count();
      if (waited < kMaxTfWaitS || waited_by_clock < kMaxTfWaitS) return;
    }  // given up: mapped at the last pose rather than lost
    map(oldest);
    waiting_for_tf_.pop_front();
  }
}

void StereoMappingNode::map(const RigFrame& frame) {
  const auto start = std::chrono::steady_clock::now();
  if (!mapper_) {
    const MergedCameraRig rig = mergeCameraRigs(mapping_.rig, frame.rig, mapping_.calibration_tolerance);
    for (const std::string& warning : rig.warnings) ROS_WARN_STREAM("stereonav_node: " << warning);
    mapper_ = std::make_unique<StereoMapper>(mapping_, rig.rig);
    panels_ = std::make_unique<DebugPanelRenderer>(mapping_, rig.rig);
  }
  if (frame.odometry) {
    last_pose_ = *frame.odometry;
  } else {
    ++frames_without_odometry_;
  }
  mapper_->process(frame, last_pose_);
  path_.push_back(last_pose_);
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  total_ms_ += ms;
  max_ms_ = std::max(max_ms_, ms);

  const ros::Time stamp = mrpt::ros1bridge::toROS(frame.timestamp);
  last_stamp_ = stamp;
  if (!ros::ok()) return;
  sensor_msgs::LaserScan scan;
  mrpt::ros1bridge::toROS(*mapper_->virtualScan(), scan);
  scan.header.stamp = stamp;
  scan.header.frame_id = options_.base_frame;
  scan_publisher_.publish(scan);
  if (panel_publisher_.getNumSubscribers() > 0) {
    std_msgs::Header header;
    header.stamp = stamp;
    header.frame_id = options_.base_frame;
    const cv::Mat panel = panels_->render(mapper_->scanner(), path_.size() - 1, last_pose_);
    panel_publisher_.publish(cv_bridge::CvImage(header, sensor_msgs::image_encodings::BGR8, panel).toImageMsg());
  }
  if (path_.size() % static_cast<size_t>(options_.map_every_frames) == 0) publishMap(stamp);
  std_msgs::UInt32 frames;
  frames.data = static_cast<uint32_t>(path_.size());
  frames_publisher_.publish(frames);
}

void StereoMappingNode::publishMap(const ros::Time& stamp) {
  const DisparityTaggedGrid grid = gridOfMap(mapper_->map(), mapping_.grid.stereo.update.scale);
  std_msgs::Header header;
  header.stamp = stamp;
  header.frame_id = options_.odom_frame;
  nav_msgs::OccupancyGrid message;
  mrpt::ros1bridge::toROS(toMrptOccupancyGrid(grid), message, header);
  map_publisher_.publish(message);
}

size_t StereoMappingNode::finish() {
  assembler_.finish();
  mapReadyFrames();
  while (!waiting_for_tf_.empty()) {
    map(waiting_for_tf_.front().frame);
    waiting_for_tf_.pop_front();
  }
  if (mapper_ && ros::ok()) publishMap(last_stamp_);
  return path_.size();
}

void StereoMappingNode::saveMap(const std::string& prefix) const {
  if (!mapper_) throw std::runtime_error(prefix + ": no frame was mapped, no map to save");
  saveMapOutputs(mapper_->map(), mapping_.grid.stereo.update.scale, path_, prefix);
}

std::string StereoMappingNode::summary() const {
  std::ostringstream text;
  text.precision(3);
  text << "mapped " << path_.size() << " frames";
  if (!path_.empty()) {
    text << ", " << total_ms_ / static_cast<double>(path_.size()) << " ms per frame (max " << max_ms_
         << " ms)";
  }
  if (frames_without_odometry_ > 0) text << ", " << frames_without_odometry_ << " without odometry";
  const std::string skipped = assembler_.skipped().summary();
  if (!skipped.empty()) text << "; " << skipped;
  return text.str();
}

}  // namespace stereonav
