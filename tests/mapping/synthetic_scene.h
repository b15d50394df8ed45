#pragma once

#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt/system/datetime.h>

#include <opencv2/core.hpp>

#include <cstdint>
#include <vector>

#include "observations/rig_frame.h"
#include "rig/camera_rig.h"

namespace stereonav::testing {

// A vertical wall on the floor plane from (x0, y0) to (x1, y1), from the floor up to `height`.
struct Wall {
  double x0, y0, x1, y1;
  double height = 2.0;
};

// A world of textured walls over an untextured floor under an untextured ceiling, ray-cast
// analytically: every camera of a rig is rendered from its own centre, so the images have the
// exact disparities and occlusions of the geometry. Walls carry smooth random texture fixed to
// the wall (value noise on a 3 cm lattice), which SAD matches; floor and sky are flat, which
// the texture test rejects, so the only valid disparities are the walls'.
class SyntheticScene {
 public:
  explicit SyntheticScene(std::vector<Wall> walls, uint32_t seed = 7);

  // The image of a camera with the given intrinsics whose optical frame is at `optical_pose`
  // in the world (x right, y down, z forward).
  cv::Mat1b render(const mrpt::poses::CPose3D& optical_pose, const PinholeCamera& camera) const;

  // A whole rig frame with the robot at `robot_pose`; odometry = that pose.
  RigFrame renderFrame(const CameraRig& rig, const mrpt::poses::CPose2D& robot_pose,
                       mrpt::system::TTimeStamp timestamp) const;

  // The distance along the ray from (x, y) with heading `heading` to the first wall; +inf if none.
  double rangeToWall(double x, double y, double heading) const;

 private:
  double brightness(size_t wall, double along, double up) const;

  std::vector<Wall> walls_;
  uint32_t seed_;
};

// The rig the tests map with: 320x240, f = 160, B = 0.1 m, Triclops L (left {-1,0}, top {0,-1}),
// level, 0.5 m above the floor at the robot's centre.
CameraRig testRig();

}  // namespace stereonav::testing
