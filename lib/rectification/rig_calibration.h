#pragma once

#include <mrpt/poses/CPose3D.h>

#include <opencv2/core.hpp>
#include <stdexcept>
#include <string>
#include <vector>

namespace stereonav {

// One camera as calibrated, before rectification: pinhole intrinsics, lens distortion and where
// it sits relative to the rig's reference camera.
struct CameraCalibration {
  cv::Size size;
  cv::Matx33d camera_matrix = cv::Matx33d::eye();  // [fx 0 cx; 0 fy cy; 0 0 1]
  // OpenCV's order (what MRPT's plumb_bob and ROS's plumb_bob / rational_polynomial store):
  // k1 k2 p1 p2 [k3 [k4 k5 k6]]. Empty or all zero: no distortion.
  std::vector<double> distortion;
  // OpenCV's stereoCalibrate convention: a point X in the reference camera's optical frame is
  // rotation * X + translation in this camera's (metres). Identity and zero for the reference.
  cv::Matx33d rotation = cv::Matx33d::eye();
  cv::Vec3d translation{0.0, 0.0, 0.0};

  // This camera's optical centre in the reference camera's frame.
  cv::Vec3d centreInReference() const { return -(rotation.t() * translation); }
  bool distorted() const;
};

// A calibrated head: camera 0 is the reference, cameras 1, 2, ... its secondaries, the first of
// which sits beside it (binocular or the horizontal pair of an L-shaped trinocular head).
struct RigCalibration {
  std::vector<CameraCalibration> cameras;
  // The reference camera's optical frame (x right, y down, z forward) on the robot.
  mrpt::poses::CPose3D reference_pose_on_robot;
};

// A calibration that no rectification can turn into the rig the disparity engine expects;
// what() says why.
class RectificationError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Throws RectificationError if `calibration` is incomplete: fewer than two cameras, an image size
// or focal length that is not positive.
void checkRigCalibration(const RigCalibration& calibration);

// True if the images of `calibration` need no resampling: no distortion, square pixels, the same
// size and intrinsics for every camera, the cameras parallel and in one plane facing the same
// way, the first secondary beside the reference (its offset along the reference image's x).
// `tolerance` covers rounding (pixels, metres and radians alike).
bool isRectified(const RigCalibration& calibration, double tolerance = 1e-6);

}  // namespace stereonav
