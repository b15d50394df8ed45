#pragma once

#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

#include "rectification/rig_calibration.h"

namespace stereonav {

// The board: inner corners per row and column (OpenCV's convention: 9x6 for the opencv-doc
// left01..14 / right01..14 set) and the side of one square.
struct Chessboard {
  cv::Size inner_corners{9, 6};
  double square_m = 0.025;
};

// The board's inner corners in an 8-bit grey image, refined to sub-pixel; nothing if the whole
// board is not found.
std::optional<std::vector<cv::Point2f>> findChessboardCorners(const cv::Mat& grey,
                                                              const Chessboard& board);

struct StereoCalibrationResult {
  RigCalibration calibration;        // camera 0 = left (the reference), camera 1 = right
  double rms_reprojection_px = 0.0;  // of the stereo fit, over both cameras
  size_t pairs_used = 0;             // pairs in which both images show the whole board
};

// Calibrates a stereo pair from views of a chessboard (OpenCV's stereo_calib recipe: each
// camera's intrinsics and 5 distortion coefficients first, then their relative pose with the
// intrinsics fixed). `left` and `right` are 8-bit grey images, pair by pair. Throws
// std::invalid_argument if fewer than 3 pairs show the whole board in both images.
StereoCalibrationResult calibrateStereo(const std::vector<cv::Mat>& left,
                                        const std::vector<cv::Mat>& right, const Chessboard& board);

}  // namespace stereonav
