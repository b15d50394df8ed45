#include "ros_bridge/rosbag_conversion.h"

#include <mrpt/ros1bridge/pose.h>
#include <mrpt/ros1bridge/time.h>
#include <nav_msgs/Odometry.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>

#include <cstdio>
#include <map>
#include <optional>
#include <stdexcept>

#include "common/error_text.h"
#include "ros_bridge/ros_camera_messages.h"

namespace stereonav {
namespace {

nav_msgs::Odometry odometryMessage(const mrpt::poses::CPose2D& pose, const ros::Time& stamp) {
  nav_msgs::Odometry odometry;
  odometry.header.stamp = stamp;
  odometry.header.frame_id = "odom";
  odometry.child_frame_id = "base_link";
  odometry.pose.pose = mrpt::ros1bridge::toROS_Pose(pose);
  return odometry;
}

bool endsWith(const std::string& text, const std::string& end) {
  return text.size() >= end.size() && text.compare(text.size() - end.size(), end.size(), end) == 0;
}

// The bag's topics for the head: per camera its image and CameraInfo topics (empty if absent).
struct HeadTopics {
  std::string image[kMaxRosCameras];
  std::string info[kMaxRosCameras];
  std::string odometry;
};

HeadTopics findHeadTopics(rosbag::Bag& bag) {
  rosbag::View everything(bag);
  std::map<std::string, std::string> types;  // topic -> data type
  for (const rosbag::ConnectionInfo* connection : everything.getConnections()) {
    types[connection->topic] = connection->datatype;
  }
  HeadTopics topics;
  for (size_t camera = 0; camera < kMaxRosCameras; ++camera) {
    const std::string name = std::string("/") + kRosCameraNames[camera] + "/";
    for (const char* image : {"image_rect", "image_raw"}) {
      for (const auto& [topic, type] : types) {
        if (!topics.image[camera].empty() || type != "sensor_msgs/Image" ||
            !endsWith("/" + topic, name + image)) {
          continue;
        }
        const std::string info = topic.substr(0, topic.size() - std::string(image).size()) + "camera_info";
        if (types.count(info) && types[info] == "sensor_msgs/CameraInfo") {
          topics.image[camera] = topic;
          topics.info[camera] = info;
        }
      }
    }
  }
  for (const auto& [topic, type] : types) {
    if (type == "nav_msgs/Odometry") {
      topics.odometry = topic;
      break;
    }
  }
  return topics;
}

}  // namespace

size_t writeRosbagFromRawlog(const std::string& rawlog_path, const RawlogReaderOptions& reader_options,
                             const std::string& bag_path,
                             const std::function<void(size_t)>& progress) {
  RawlogReader reader(rawlog_path, reader_options);
  const std::string temporary = bag_path + ".partial";
  size_t frames = 0;
  try {
    rosbag::Bag bag(temporary, rosbag::bagmode::Write);
    while (auto frame = reader.next()) {
      const ros::Time stamp = mrpt::ros1bridge::toROS(frame->timestamp);
      if (frame->odometry) bag.write(kRosOdometryTopic, stamp, odometryMessage(*frame->odometry, stamp));
      const std::vector<RosCameraMessage> cameras = toRosCameraMessages(*frame, "stereo");
      for (size_t camera = 0; camera < cameras.size(); ++camera) {
        const std::string topic = std::string(kRosStereoNamespace) + "/" + kRosCameraNames[camera];
        bag.write(topic + "/image_rect", stamp, cameras[camera].image);
        bag.write(topic + "/camera_info", stamp, cameras[camera].info);
      }
      ++frames;
      if (progress) progress(frames);
    }
    bag.close();
  } catch (const std::exception& e) {
    std::remove(temporary.c_str());
    throw std::runtime_error(bag_path + ": cannot write the bag: " + oneLineMessage(e.what()));
  }
  if (reader.damage()) {
    std::remove(temporary.c_str());
    throw std::runtime_error(reader.damage()->describe(rawlog_path));
  }
  if (std::rename(temporary.c_str(), bag_path.c_str()) != 0) {
    std::remove(temporary.c_str());
    throw std::runtime_error(bag_path + ": cannot move the written bag into place");
  }
  return frames;
}

RosbagConversionReport convertRosbagToRawlog(const std::string& bag_path, const RosHeadOptions& head,
                                             RawlogWriter& writer,
                                             const std::function<void(size_t)>& progress) {
  rosbag::Bag bag;
  try {
    bag.open(bag_path, rosbag::bagmode::Read);
  } catch (const std::exception& e) {
    throw std::runtime_error(bag_path + ": cannot read the bag: " + oneLineMessage(e.what()));
  }
  const HeadTopics topics = findHeadTopics(bag);
  RosbagConversionReport report;
  for (size_t camera = 0; camera < head.cameras; ++camera) {
    if (topics.image[camera].empty()) {
      throw std::runtime_error(bag_path + ": no " + kRosCameraNames[camera] + "/image_rect or " +
                               kRosCameraNames[camera] + "/image_raw topic with its camera_info");
    }
    report.image_topics += (camera ? " " : "") + topics.image[camera];
  }
  RosHeadOptions assembled = head;
  assembled.wait_for_odometry = !topics.odometry.empty();
  RosFrameAssembler assembler(assembled);
  const auto write_ready = [&] {
    while (auto frame = assembler.next()) {
      writer.write(*frame);
      ++report.frames;
      if (progress) progress(report.frames);
    }
  };
  try {
    for (const rosbag::MessageInstance& message : rosbag::View(bag)) {
      const std::string& topic = message.getTopic();
      if (topic == topics.odometry) {
        if (const auto odometry = message.instantiate<nav_msgs::Odometry>()) {
          const mrpt::poses::CPose3D pose = mrpt::ros1bridge::fromROS(odometry->pose.pose);
          assembler.addOdometry(mrpt::ros1bridge::fromROS(odometry->header.stamp),
                                mrpt::poses::CPose2D(pose));
          ++report.odometry_messages;
        }
      }
      for (size_t camera = 0; camera < head.cameras; ++camera) {
        if (topic == topics.image[camera]) {
          if (const auto image = message.instantiate<sensor_msgs::Image>()) assembler.addImage(camera, image);
        } else if (topic == topics.info[camera]) {
          if (const auto info = message.instantiate<sensor_msgs::CameraInfo>()) {
            assembler.addCameraInfo(camera, info);
          }
        }
      }
      write_ready();
    }
  } catch (const rosbag::BagException& e) {
    // A damaged bag keeps what was read before the damage, as a damaged rawlog does.
    report.damage = bag_path + ": unreadable from here on: " + oneLineMessage(e.what());
  }
  assembler.finish();
  write_ready();
  report.skipped = assembler.skipped();
  return report;
}

}  // namespace stereonav
