#pragma once

#include <mrpt/poses/CPose2D.h>

#include <string>
#include <vector>

#include "observations/rig_frame.h"
#include "rig/camera_rig.h"

namespace stereonav {

// A KITTI odometry sequence laid out as image_l/NNNNNN.png, image_r/NNNNNN.png (rectified grey
// pairs), calib.txt (the two 3x4 projection matrices, left then right, one per line, row-major)
// and poses.txt (per frame the 3x4 pose [R|t] of the left camera in the first frame's camera
// coordinates: x right, y down, z forward).
struct KittiSequence {
  std::string directory;
  CameraRig rig;  // reference = left camera, the right one at {1, 0}; camera_height_m above the floor
  // The left camera's true poses on the floor plane (robot frame: x forward, y left), frame 0
  // at the origin.
  std::vector<mrpt::poses::CPose2D> poses;
};

// Reads calib.txt and poses.txt of `directory`. The camera is taken as level, `camera_height_m`
// above the road. Throws std::runtime_error naming the file on anything missing or malformed.
KittiSequence loadKittiSequence(const std::string& directory, double camera_height_m);

// Frame `index` (images, rig, 10 Hz timestamp) with `odometry` as its odometry. Throws
// std::runtime_error naming an image that cannot be read.
RigFrame kittiFrame(const KittiSequence& sequence, size_t index,
                    const mrpt::poses::CPose2D& odometry);

}  // namespace stereonav
