#pragma once

#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include <chrono>
#include <deque>
#include <memory>
#include <string>
#include <vector>

#include "mapping/debug_panel.h"
#include "mapping/mapping_options.h"
#include "mapping/stereo_mapper.h"
#include "ros_bridge/ros_frame_assembler.h"

namespace stereonav {

// What the node adds to the mapping ini (ROS parameters of its private namespace).
struct MappingNodeOptions {
  // "topic": nav_msgs/Odometry on `odom`; "tf": the transform from odom_frame to base_frame at
  // each capture's instant.
  std::string odometry_source = "topic";
  std::string odom_frame = "odom";  // also the frame of the published map
  std::string base_frame = "base_link";
  int map_every_frames = 5;  // the map is published after every N-th frame mapped
};

// Reads ~odometry_source, ~odom_frame, ~base_frame and ~map_every_frames; throws
// std::invalid_argument naming the parameter for a bad value.
MappingNodeOptions loadMappingNodeOptions(const ros::NodeHandle& private_node);

// The mapping pipeline of `stereonav map` as a ROS 1 node, frame for frame the same map from the
// same frames (StereoMapper at the odometry pose of each capture):
//   subscribes  stereo/<camera>/image_rect and stereo/<camera>/camera_info for the head's cameras
//               (left, right [, top]: ros_camera_messages.h; remap image_rect to image_raw for an
//               unrectified head: it is rectified from its CameraInfo), and odom
//               (nav_msgs/Odometry) unless odometry comes from tf;
//   publishes   map (nav_msgs/OccupancyGrid, latched, in odom_frame), stereo_scan
//               (sensor_msgs/LaserScan, the frame's column projection as a virtual laser, in
//               base_frame), debug_panel (sensor_msgs/Image, only while someone subscribes) and
//               frames_mapped (std_msgs/UInt32, latched).
class StereoMappingNode {
 public:
  StereoMappingNode(ros::NodeHandle& node, const MappingOptions& mapping,
                    const MappingNodeOptions& options);

  // After the last message: maps the frames still waiting and publishes the map (if ROS is still
  // up). Returns the number of frames mapped in all.
  size_t finish();
  // Writes the map as `stereonav map` does (map_outputs.h). Throws std::runtime_error.
  void saveMap(const std::string& prefix) const;
  // "mapped N frames, mean X ms, max Y ms per frame" and what was skipped, for the log.
  std::string summary() const;

 private:
  void onOdometry(const nav_msgs::Odometry::ConstPtr& odometry);
  void mapReadyFrames();
  // The frame's odometry from tf, or false if tf cannot tell it yet.
  bool odometryFromTf(RigFrame& frame);
  void map(const RigFrame& frame);
  void publishMap(const ros::Time& stamp);

  MappingOptions mapping_;
  MappingNodeOptions options_;
  RosFrameAssembler assembler_;
  std::vector<ros::Subscriber> subscribers_;
  ros::Publisher map_publisher_, scan_publisher_, panel_publisher_, frames_publisher_;
  std::unique_ptr<tf2_ros::Buffer> tf_buffer_;
  std::unique_ptr<tf2_ros::TransformListener> tf_listener_;
  ros::Timer tf_timer_;
  // Captures waiting for their odometry tf, with when each arrived.
  struct WaitingFrame {
    RigFrame frame;
    std::chrono::steady_clock::time_point arrived;
  };
  std::deque<WaitingFrame> waiting_for_tf_;
  std::unique_ptr<StereoMapper> mapper_;
  std::unique_ptr<DebugPanelRenderer> panels_;
  std::vector<mrpt::poses::CPose2D> path_;
  mrpt::poses::CPose2D last_pose_;
  ros::Time last_stamp_;  // of the last frame mapped
  size_t frames_without_odometry_ = 0;
  double total_ms_ = 0.0, max_ms_ = 0.0;
};

}  // namespace stereonav
