#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "rectification/rig_calibration.h"
#include "rig/camera_rig.h"

namespace stereonav {

// The CameraRig of a calibration that needs no resampling (isRectified): the reference camera's
// intrinsics, the unit baseline B = the distance to camera 1, every secondary at its offset / B.
CameraRig rigOfRectifiedCalibration(const RigCalibration& calibration);

// Turns the raw images of a calibrated head into the rectified rig the disparity engine expects
// (paper section 2.1: the Triclops does this in hardware before matching): every camera rotated
// into one common orientation and resampled through one shared pinhole camera without
// distortion. The maps are computed once, here, and reused for every frame.
//
// The common orientation: x along the baseline from the reference to camera 1 (pointing the way
// the reference image's x does), z normal to the plane through the cameras' centres (three or
// more cameras) or the two cameras' mean viewing direction made normal to x (two), y = z x x.
// With every centre in the plane z = 0 of that frame, each secondary differs from the reference by
// a pure image shift of (bx d, by d): camera 1 on the reference's rows (by = 0) and, in an
// L-shaped head, the top camera on its columns up to bx = (its offset along the first baseline) /
// B, which the rig carries so the matcher follows it. This is OpenCV's stereoRectify frame for a
// pair, extended to a third camera without the small vertical parallax that rectifying it pairwise
// against the reference would leave.
//
// The shared camera: the smallest focal length of the cameras (no camera is magnified), the
// reference's image size, and the principal point that centres the cameras' mean view.
class StereoRectifier {
 public:
  // Throws RectificationError saying why if the calibration cannot be rectified: incomplete, a
  // zero baseline, three or more centres on one line or off one plane, or a camera looking more
  // than 45 degrees away from the common viewing direction.
  explicit StereoRectifier(const RigCalibration& calibration);

  const RigCalibration& calibration() const { return calibration_; }
  // The rectified head, mounted on the robot where the calibration's reference is, turned by the
  // rectifying rotation.
  const CameraRig& rig() const { return rig_; }

  // The rectified images, one per raw image in camera order. Throws std::invalid_argument if their
  // number or a size differs from the calibration's.
  std::vector<cv::Mat> rectify(const std::vector<cv::Mat>& images) const;

  // Where raw pixels of camera `camera` land in its rectified image (no resampling).
  std::vector<cv::Point2f> rectifyPoints(size_t camera, const std::vector<cv::Point2f>& raw) const;

 private:
  RigCalibration calibration_;
  std::vector<cv::Matx33d> rotations_;  // raw camera frame -> common rectified frame
  cv::Matx33d new_camera_matrix_;
  CameraRig rig_;
  std::vector<cv::Mat> map_xy_, map_interpolation_;  // cv::initUndistortRectifyMap's CV_16SC2 pair
};

}  // namespace stereonav
