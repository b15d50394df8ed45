#pragma once

#include <string>

#include "command_line.h"

namespace stereonav::app {

// `stereonav convert rosbag` (a bag of a stereo head into a rawlog) and `convert to-rosbag` (a
// rawlog into a bag of stereo_image_proc's topics); built with ROS 1 only.
int runRosbagConversion(const std::string& direction, CommandLine& command_line);

}  // namespace stereonav::app
