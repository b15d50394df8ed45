#pragma once

#include <mrpt/system/datetime.h>

#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "observations/rig_frame.h"
#include "rectification/stereo_rectifier.h"

namespace stereonav {

// Turns the images of one capture and the calibration they were recorded with into a RigFrame:
// a rig that is rectified already passes through untouched; any other is rectified by a
// StereoRectifier, made once and kept for as long as the calibration stays the same (a rawlog
// carries its calibration in every observation). A calibration file (given by the user) replaces
// what the observations recorded, except where the head sits on the robot. Safe to share between
// threads.
class FrameRectifier {
 public:
  // `calibration_file`: cameras in rig order (reference first) with every pose relative to the
  // reference; nothing = use the recorded calibration.
  explicit FrameRectifier(std::optional<RigCalibration> calibration_file = std::nullopt);

  bool hasCalibrationFile() const { return calibration_file_.has_value(); }

  // `images` in camera order (reference first); `file_reference`: which camera of the calibration
  // file is the reference (1 for a pair whose reference is its right camera). Throws ObservationRejected naming `label`:
  // kWrongImageFormat if an image's size is not its camera's, kNotRectified (with the reason) if
  // the calibration cannot be rectified, kWrongCameraCount if the calibration file has another
  // number of cameras.
  RigFrame frame(const RigCalibration& recorded, const std::vector<cv::Mat>& images,
                 mrpt::system::TTimeStamp timestamp, const std::string& label,
                 size_t file_reference = 0);

 private:
  std::optional<RigCalibration> calibration_file_;
  std::mutex mutex_;
  std::unique_ptr<StereoRectifier> rectifier_;
};

bool operator==(const CameraCalibration& a, const CameraCalibration& b);
bool operator==(const RigCalibration& a, const RigCalibration& b);

}  // namespace stereonav
