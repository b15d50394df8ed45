#include "rectification/stereo_rectifier.h"

#include <mrpt/core/bits_math.h>
#include <mrpt/math/CMatrixFixed.h>

#include <algorithm>
#include <cmath>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace stereonav {
namespace {

constexpr double kMaxViewAngleDeg = 45.0;
// A third centre closer than this (relative to the baselines) to the line through the first two
// leaves the plane of the centres undefined.
constexpr double kMinCollinearitySine = 0.05;
// With four or more cameras, a centre farther than this fraction of B from the common plane
// would keep a depth-dependent parallax after rectification.
constexpr double kMaxOffPlaneFraction = 0.01;

cv::Vec3d normalized(const cv::Vec3d& v) { return v * (1.0 / cv::norm(v)); }

mrpt::poses::CPose3D rotationPose(const cv::Matx33d& rotation) {
  mrpt::math::CMatrixDouble33 matrix;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) matrix(r, c) = rotation(r, c);
  }
  return mrpt::poses::CPose3D(matrix, mrpt::math::CVectorFixedDouble<3>());
}

// The rows of the common rectified frame, in the reference camera's coordinates.
cv::Matx33d commonOrientation(const RigCalibration& calibration) {
  const auto& cameras = calibration.cameras;
  std::vector<cv::Vec3d> centres;
  for (const auto& camera : cameras) centres.push_back(camera.centreInReference());
  const double baseline = cv::norm(centres[1]);
  if (!(baseline > 1e-9)) {
    throw RectificationError("camera 1 sits on the reference camera (zero baseline)");
  }
  cv::Vec3d x = centres[1] * (1.0 / baseline);
  if (x[0] < 0) x = -x;

  cv::Vec3d z;
  if (cameras.size() == 2) {
    z = cv::Vec3d(0, 0, 1) + cameras[1].rotation.t() * cv::Vec3d(0, 0, 1);
  } else {
    cv::Vec3d normal;
    double best = 0.0;
    for (size_t k = 2; k < centres.size(); ++k) {
      const cv::Vec3d candidate = x.cross(centres[k]);
      const double sine = cv::norm(candidate) / cv::norm(centres[k]);
      if (sine > best) best = sine, normal = candidate;
    }
    if (best < kMinCollinearitySine) {
      throw RectificationError(
          "the cameras' centres lie on one line: a collinear head has no common image plane "
          "that puts every camera on the reference's rows or columns; calibrate it as pairs");
    }
    z = normalized(normal);
    if (z[2] < 0) z = -z;
    for (size_t k = 2; k < centres.size(); ++k) {
      if (std::abs(centres[k].dot(z)) > kMaxOffPlaneFraction * baseline) {
        throw RectificationError("camera " + std::to_string(k) +
                                 " is off the plane of the other cameras' centres by " +
                                 std::to_string(std::abs(centres[k].dot(z))) + " m");
      }
    }
  }
  z = normalized(z - z.dot(x) * x);
  const cv::Vec3d y = z.cross(x);
  for (size_t k = 0; k < cameras.size(); ++k) {
    const cv::Vec3d view = cameras[k].rotation.t() * cv::Vec3d(0, 0, 1);
    const double angle = mrpt::RAD2DEG(std::acos(std::clamp(view.dot(z), -1.0, 1.0)));
    if (angle > kMaxViewAngleDeg) {
      throw RectificationError("camera " + std::to_string(k) + " looks " + std::to_string(angle) +
                               " degrees away from the direction normal to the cameras' "
                               "baselines (more than 45): no common image plane sees its view");
    }
  }
  return cv::Matx33d(x[0], x[1], x[2], y[0], y[1], y[2], z[0], z[1], z[2]);
}

}  // namespace

CameraRig rigOfRectifiedCalibration(const RigCalibration& calibration) {
  checkRigCalibration(calibration);
  const CameraCalibration& reference = calibration.cameras[0];
  CameraRig rig;
  rig.reference.width = reference.size.width;
  rig.reference.height = reference.size.height;
  rig.reference.focal_px = reference.camera_matrix(0, 0);
  rig.reference.cx = reference.camera_matrix(0, 2);
  rig.reference.cy = reference.camera_matrix(1, 2);
  rig.baseline_m = cv::norm(calibration.cameras[1].centreInReference());
  rig.secondaries.clear();
  for (size_t k = 1; k < calibration.cameras.size(); ++k) {
    const cv::Vec3d centre = calibration.cameras[k].centreInReference();
    rig.secondaries.push_back({centre[0] / rig.baseline_m, centre[1] / rig.baseline_m});
  }
  rig.pose_on_robot = calibration.reference_pose_on_robot;
  return rig;
}

StereoRectifier::StereoRectifier(const RigCalibration& calibration) : calibration_(calibration) {
  checkRigCalibration(calibration_);
  const auto& cameras = calibration_.cameras;
  const cv::Matx33d common = commonOrientation(calibration_);

  double focal = cameras[0].camera_matrix(0, 0);
  for (const auto& camera : cameras) {
    focal = std::min({focal, camera.camera_matrix(0, 0), camera.camera_matrix(1, 1)});
  }
  const cv::Size size = cameras[0].size;
  const cv::Matx33d unit_centre(focal, 0, 0, 0, focal, 0, 0, 0, 1);
  cv::Point2d mean_view(0, 0);
  for (const auto& camera : cameras) {
    rotations_.push_back(common * camera.rotation.t());
    const std::vector<cv::Point2d> centre{
        {(camera.size.width - 1) / 2.0, (camera.size.height - 1) / 2.0}};
    std::vector<cv::Point2d> rectified;
    cv::undistortPoints(centre, rectified, camera.camera_matrix, camera.distortion,
                        rotations_.back(), unit_centre);
    mean_view += rectified[0] * (1.0 / static_cast<double>(cameras.size()));
  }
  new_camera_matrix_ = cv::Matx33d(focal, 0, (size.width - 1) / 2.0 - mean_view.x, 0, focal,
                                   (size.height - 1) / 2.0 - mean_view.y, 0, 0, 1);

  for (size_t k = 0; k < cameras.size(); ++k) {
    cv::Mat map_xy, map_interpolation;
    cv::initUndistortRectifyMap(cameras[k].camera_matrix, cameras[k].distortion, rotations_[k],
                                new_camera_matrix_, size, CV_16SC2, map_xy, map_interpolation);
    map_xy_.push_back(map_xy);
    map_interpolation_.push_back(map_interpolation);
  }

  rig_.reference.width = size.width;
  rig_.reference.height = size.height;
  rig_.reference.focal_px = focal;
  rig_.reference.cx = new_camera_matrix_(0, 2);
  rig_.reference.cy = new_camera_matrix_(1, 2);
  rig_.baseline_m = cv::norm(cameras[1].centreInReference());
  rig_.secondaries.clear();
  for (size_t k = 1; k < cameras.size(); ++k) {
    const cv::Vec3d offset = common * cameras[k].centreInReference();
    rig_.secondaries.push_back({offset[0] / rig_.baseline_m, offset[1] / rig_.baseline_m});
  }
  rig_.pose_on_robot = calibration_.reference_pose_on_robot + rotationPose(common.t());
}

std::vector<cv::Mat> StereoRectifier::rectify(const std::vector<cv::Mat>& images) const {
  const auto& cameras = calibration_.cameras;
  if (images.size() != cameras.size()) {
    throw std::invalid_argument("rectify: " + std::to_string(images.size()) + " images for " +
                                std::to_string(cameras.size()) + " calibrated cameras");
  }
  std::vector<cv::Mat> rectified(images.size());
  for (size_t k = 0; k < images.size(); ++k) {
    if (images[k].size() != cameras[k].size) {
      throw std::invalid_argument(
          "rectify: camera " + std::to_string(k) + " image is " + std::to_string(images[k].cols) +
          "x" + std::to_string(images[k].rows) + ", its calibration is for " +
          std::to_string(cameras[k].size.width) + "x" + std::to_string(cameras[k].size.height));
    }
    cv::remap(images[k], rectified[k], map_xy_[k], map_interpolation_[k], cv::INTER_LINEAR,
              cv::BORDER_CONSTANT);
  }
  return rectified;
}

std::vector<cv::Point2f> StereoRectifier::rectifyPoints(size_t camera,
                                                        const std::vector<cv::Point2f>& raw) const {
  std::vector<cv::Point2f> rectified;
  if (raw.empty()) return rectified;
  const CameraCalibration& calibration = calibration_.cameras.at(camera);
  cv::undistortPoints(raw, rectified, calibration.camera_matrix, calibration.distortion,
                      rotations_.at(camera), new_camera_matrix_);
  return rectified;
}

}  // namespace stereonav
