#include "rectification/rig_calibration.h"

#include <cmath>

namespace stereonav {

bool CameraCalibration::distorted() const {
  for (const double k : distortion) {
    if (k != 0.0) return true;
  }
  return false;
}

void checkRigCalibration(const RigCalibration& calibration) {
  if (calibration.cameras.size() < 2) {
    throw RectificationError("a stereo head needs at least two calibrated cameras, got " +
                             std::to_string(calibration.cameras.size()));
  }
  for (size_t k = 0; k < calibration.cameras.size(); ++k) {
    const CameraCalibration& camera = calibration.cameras[k];
    const std::string which = "camera " + std::to_string(k);
    if (camera.size.width <= 0 || camera.size.height <= 0) {
      throw RectificationError(which + ": no image size in the calibration");
    }
    if (!(camera.camera_matrix(0, 0) > 0) || !(camera.camera_matrix(1, 1) > 0)) {
      throw RectificationError(which + ": no focal length in the calibration");
    }
    const size_t n = camera.distortion.size();
    if (n != 0 && n != 4 && n != 5 && n != 8) {
      throw RectificationError(which + ": " + std::to_string(n) +
                               " distortion coefficients; expected 4, 5 or 8 (k1 k2 p1 p2 k3 "
                               "k4 k5 k6)");
    }
  }
}

bool isRectified(const RigCalibration& calibration, double tolerance) {
  const auto near = [&](double a, double b) { return std::abs(a - b) <= tolerance; };
  const CameraCalibration& reference = calibration.cameras.at(0);
  const cv::Matx33d& k0 = reference.camera_matrix;
  for (size_t k = 0; k < calibration.cameras.size(); ++k) {
    const CameraCalibration& camera = calibration.cameras[k];
    const cv::Matx33d& K = camera.camera_matrix;
    if (camera.distorted() || camera.size != reference.size || !near(K(0, 0), K(1, 1)) ||
        !near(K(0, 1), 0.0) || !near(K(0, 0), k0(0, 0)) || !near(K(0, 2), k0(0, 2)) ||
        !near(K(1, 2), k0(1, 2))) {
      return false;
    }
    if (cv::norm(camera.rotation - cv::Matx33d::eye(), cv::NORM_INF) > tolerance) return false;
    if (!near(camera.centreInReference()[2], 0.0)) return false;
  }
  const cv::Vec3d first = calibration.cameras.at(1).centreInReference();
  return near(first[1], 0.0) && !near(first[0], 0.0);
}

}  // namespace stereonav
