#pragma once

#include <mrpt/poses/CPose2D.h>

#include <optional>
#include <string>
#include <vector>

#include "observations/rig_frame.h"
#include "rig/camera_rig.h"

namespace stereonav {

// A KITTI odometry sequence laid out as image_l/NNNNNN.png, image_r/NNNNNN.png (or KITTI's own
// image_0/, image_1/; rectified grey pairs), calib.txt (the two 3x4 projection matrices, left then
// right, one per line, row-major, optionally labelled "P0:") and, optionally, poses.txt (per frame
// the 3x4 pose [R|t] of the left camera in the first frame's camera coordinates: x right, y down,
// z forward).
struct KittiSequence {
  std::string left_directory;
  std::string right_directory;
  size_t frames = 0;  // the consecutive left images from 000000.png
  CameraRig rig;      // reference = left camera, the right one at {1, 0}; camera_height_m above the floor
  // The left camera's true poses on the floor plane (robot frame: x forward, y left), frame 0
  // at the origin; empty without poses.txt.
  std::vector<mrpt::poses::CPose2D> poses;
};

// Reads calib.txt and poses.txt of `directory`. The camera is taken as level, `camera_height_m`
// above the road. Throws std::runtime_error naming the file on anything missing or malformed.
KittiSequence loadKittiSequence(const std::string& directory, double camera_height_m);

// Frame `index` (images, rig, 10 Hz timestamp) with `odometry` as its odometry. Throws
// std::runtime_error naming an image that cannot be read.
RigFrame kittiFrame(const KittiSequence& sequence, size_t index,
                    const std::optional<mrpt::poses::CPose2D>& odometry);

// The error a wheeled base's odometry would add to a true trajectory: every distance scaled by
// 1 + distance_bias, and the heading drifting by a Gaussian of drift_deg_per_m per metre driven.
struct OdometryError {
  double distance_bias = 0.0;
  double drift_deg_per_m = 0.0;
  unsigned seed = 1;
};

// `truth` as that odometry would report it, from the same first pose.
std::vector<mrpt::poses::CPose2D> odometryWithError(const std::vector<mrpt::poses::CPose2D>& truth,
                                                    const OdometryError& error);

}  // namespace stereonav
