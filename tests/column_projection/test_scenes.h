#pragma once

#include <mrpt/core/bits_math.h>
#include <opencv2/core.hpp>

#include <cmath>

#include "column_projection/projection_options.h"
#include "disparity/disparity_image.h"
#include "rig/camera_rig.h"

namespace stereonav {

// A 201 x 101 camera with f = 100 px, principal point at the centre pixel (100, 50), B = 0.1 m:
// a pixel u columns right of the centre at depth Z is u Z / 100 m to the right, and d = 10 / Z.
inline CameraRig testRig(double mount_x, double mount_y, double yaw_deg, double tilt_down_deg) {
  CameraRig rig;
  rig.reference.width = 201;
  rig.reference.height = 101;
  rig.reference.focal_px = 100.0;
  rig.reference.cx = 100.0;
  rig.reference.cy = 50.0;
  rig.baseline_m = 0.1;
  rig.pose_on_robot = CameraRig::opticalPoseOnRobot(mount_x, mount_y, 0.5, mrpt::DEG2RAD(yaw_deg),
                                                    mrpt::DEG2RAD(tilt_down_deg));
  return rig;
}

inline ProjectionOptions bodyVolume(double robot_height_m) {
  ProjectionOptions options;
  options.floor_clearance_m = 0.05;
  options.robot_height_m = robot_height_m;
  return options;
}

// Level camera 0.5 m up, looking along a corridor (heights: 0.5 - (y - 50) Z / 100):
//  - rows 0..9: a shelf at Z = 1.25 m (d = 8), 1.01 m and more above the floor;
//  - rows 10..74: a wall at Z = 2 m (d = 5);
//  - rows 75..100: the floor, d = (y - 50) / 5 (row 75 meets the wall at Z = 2, row 100 is 1 m);
//  - columns 150..160, rows 40..60: a box face at Z = 1.25 m (d = 8), 0.375..0.625 m high.
inline cv::Mat1f levelCorridor() {
  cv::Mat1f disparity(101, 201);
  for (int y = 0; y < 101; ++y) {
    const float d = y < 10 ? 8.0f : y < 75 ? 5.0f : (y - 50) / 5.0f;
    disparity.row(y).setTo(d);
  }
  disparity(cv::Rect(150, 40, 11, 21)).setTo(8.0f);
  return disparity;
}

// Camera 0.5 m up, pitched 30 degrees down, over a textured floor with a box in front: the box
// face is the plane 1 m ahead, 0.3 m tall, 0.4 m wide, centred on the optical axis. Ray-cast from
// the geometry written out by hand: per unit of camera depth Z a pixel's ray goes
// forward cos30 - v sin30, left -u, up -sin30 - v cos30, with u = (x-100)/100, v = (y-50)/100.
inline cv::Mat1f tiltedFloorWithBox() {
  const double cos30 = std::sqrt(3.0) / 2.0, sin30 = 0.5;
  cv::Mat1f disparity(101, 201, kInvalidDisparity);
  for (int y = 0; y < 101; ++y) {
    for (int x = 0; x < 201; ++x) {
      const double u = (x - 100) / 100.0, v = (y - 50) / 100.0;
      const double forward = cos30 - v * sin30, left = -u, up = -sin30 - v * cos30;
      double depth = up < 0 ? 0.5 / -up : HUGE_VAL;  // the floor
      if (forward > 0) {
        const double z_box = 1.0 / forward;
        const double height = 0.5 + z_box * up;
        if (height >= 0.0 && height <= 0.3 && std::abs(z_box * left) <= 0.2) {
          depth = std::min(depth, z_box);
        }
      }
      if (depth < HUGE_VAL) disparity(y, x) = static_cast<float>(10.0 / depth);
    }
  }
  return disparity;
}

}  // namespace stereonav
