// stereonav_node: the mapping pipeline as a ROS 1 node (lib/ros_bridge/stereo_mapping_node.h).
//   rosrun-style:  stereonav_node _config:=ini/office_run.ini [_output_prefix:=out/ros_map]
//                  [_odometry_source:=topic|tf] [_odom_frame:=odom] [_base_frame:=base_link]
//                  [_map_every_frames:=5]
// Ctrl-C or SIGTERM maps what has arrived, writes the map files when _output_prefix is set, and
// prints a summary line.
#include <ros/ros.h>

#include <csignal>
#include <iostream>

#include "common/error_text.h"
#include "mapping/mapping_options.h"
#include "ros_bridge/stereo_mapping_node.h"

namespace {

void requestShutdown(int) { ros::requestShutdown(); }

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "stereonav_node", ros::init_options::NoSigintHandler);
  std::signal(SIGINT, requestShutdown);
  std::signal(SIGTERM, requestShutdown);
  try {
    ros::NodeHandle node;
    ros::NodeHandle private_node("~");
    std::string config;
    if (!private_node.getParam("config", config)) {
      std::cerr << "stereonav_node: ~config: the mapping ini is required (e.g. _config:=ini/office_run.ini)\n";
      return 2;
    }
    const std::string output_prefix = private_node.param<std::string>("output_prefix", "");
    const stereonav::MappingOptions mapping = stereonav::loadMappingOptionsFile(config);
    stereonav::StereoMappingNode mapper(node, mapping, stereonav::loadMappingNodeOptions(private_node));
    ros::spin();
    mapper.finish();
    std::cerr << "stereonav_node: " << mapper.summary() << "\n";
    if (!output_prefix.empty()) mapper.saveMap(output_prefix);
  } catch (const std::exception& e) {
    std::cerr << "stereonav_node: " << stereonav::oneLineMessage(e.what()) << "\n";
    return 2;
  }
  return 0;
}
