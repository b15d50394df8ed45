#include "observations/frame_rectifier.h"

#include "observations/rig_observations.h"
#include "rectification/calibration_files.h"

namespace stereonav {

bool operator==(const CameraCalibration& a, const CameraCalibration& b) {
  return a.size == b.size && a.camera_matrix == b.camera_matrix && a.distortion == b.distortion &&
         a.rotation == b.rotation && a.translation == b.translation;
}

bool operator==(const RigCalibration& a, const RigCalibration& b) {
  return a.cameras == b.cameras && a.reference_pose_on_robot == b.reference_pose_on_robot;
}

FrameRectifier::FrameRectifier(std::optional<RigCalibration> calibration_file)
    : calibration_file_(std::move(calibration_file)) {}

RigFrame FrameRectifier::frame(const RigCalibration& recorded, const std::vector<cv::Mat>& images,
                               mrpt::system::TTimeStamp timestamp, const std::string& label,
                               size_t file_reference) {
  RigCalibration calibration = recorded;
  if (calibration_file_) {
    if (calibration_file_->cameras.size() != images.size()) {
      throw ObservationRejected(RejectReason::kWrongCameraCount,
                                label + ": " + std::to_string(images.size()) +
                                    " cameras, the calibration file has " +
                                    std::to_string(calibration_file_->cameras.size()));
    }
    calibration.cameras = withReference(*calibration_file_, file_reference).cameras;
  }
  std::vector<cv::Size> sizes;
  for (const cv::Mat& image : images) sizes.push_back(image.size());
  try {
    calibration = withImageSizes(std::move(calibration), sizes);
  } catch (const RectificationError& e) {
    throw ObservationRejected(RejectReason::kWrongImageFormat, label + ": " + e.what());
  }

  RigFrame frame;
  frame.timestamp = timestamp;
  std::vector<cv::Mat> rectified;
  try {
    checkRigCalibration(calibration);
    if (isRectified(calibration)) {
      frame.rig = rigOfRectifiedCalibration(calibration);
      rectified = images;
    } else {
      std::lock_guard<std::mutex> lock(mutex_);
      if (!rectifier_ || !(rectifier_->calibration() == calibration)) {
        rectifier_ = std::make_unique<StereoRectifier>(calibration);
      }
      frame.rig = rectifier_->rig();
      rectified = rectifier_->rectify(images);
    }
  } catch (const RectificationError& e) {
    throw ObservationRejected(RejectReason::kNotRectified,
                              label + ": cannot be rectified: " + e.what());
  }
  frame.reference = rectified[0];
  frame.secondaries.assign(rectified.begin() + 1, rectified.end());
  try {
    checkRigFrame(frame);
  } catch (const std::invalid_argument& e) {
    throw ObservationRejected(RejectReason::kWrongImageFormat, label + ": " + e.what());
  }
  return frame;
}

}  // namespace stereonav
