#pragma once

#include <mrpt/poses/CPose2D.h>
#include <mrpt/system/datetime.h>

#include <opencv2/core.hpp>
#include <optional>
#include <vector>

#include "rig/camera_rig.h"

namespace stereonav {

// One capture of the stereo head (paper section 2: the Triclops delivers the three corrected
// images of one instant): the reference image, one image per secondary camera, the rig that took
// them, and where odometry placed the robot at that instant, if it was recorded.
struct RigFrame {
  mrpt::system::TTimeStamp timestamp;
  cv::Mat reference;                 // 8-bit grey or BGR, rig.reference.width x height
  std::vector<cv::Mat> secondaries;  // same size and type, in rig.secondaries order
  CameraRig rig;
  // Absolute odometry pose of the robot (x forward, y left), as the robot's own dead reckoning
  // reports it; absent when the robot gave none for this capture.
  std::optional<mrpt::poses::CPose2D> odometry;
};

// Throws std::invalid_argument saying what is wrong if the frame's images do not match its rig
// (one image per secondary camera, every image of the rig's size and of one 8-bit type).
void checkRigFrame(const RigFrame& frame);

}  // namespace stereonav
