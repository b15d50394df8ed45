#include "rectification/chessboard_calibration.h"

#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace stereonav {

std::optional<std::vector<cv::Point2f>> findChessboardCorners(const cv::Mat& grey,
                                                              const Chessboard& board) {
  std::vector<cv::Point2f> corners;
  if (!cv::findChessboardCorners(grey, board.inner_corners, corners,
                                 cv::CALIB_CB_ADAPTIVE_THRESH | cv::CALIB_CB_NORMALIZE_IMAGE)) {
    return std::nullopt;
  }
  cv::cornerSubPix(grey, corners, {11, 11}, {-1, -1},
                   {cv::TermCriteria::COUNT + cv::TermCriteria::EPS, 30, 0.01});
  return corners;
}

StereoCalibrationResult calibrateStereo(const std::vector<cv::Mat>& left,
                                        const std::vector<cv::Mat>& right, const Chessboard& board) {
  if (left.size() != right.size() || left.empty()) {
    throw std::invalid_argument("calibration: " + std::to_string(left.size()) + " left and " +
                                std::to_string(right.size()) + " right images");
  }
  std::vector<cv::Point3f> board_points;
  for (int row = 0; row < board.inner_corners.height; ++row) {
    for (int column = 0; column < board.inner_corners.width; ++column) {
      board_points.emplace_back(static_cast<float>(column * board.square_m),
                                static_cast<float>(row * board.square_m), 0.0f);
    }
  }
  std::vector<std::vector<cv::Point3f>> object_points;
  std::vector<std::vector<cv::Point2f>> left_points, right_points;
  for (size_t i = 0; i < left.size(); ++i) {
    if (left[i].size() != left[0].size() || right[i].size() != right[0].size()) {
      throw std::invalid_argument("calibration: pair " + std::to_string(i) +
                                  " differs in image size from the first pair");
    }
    auto in_left = findChessboardCorners(left[i], board);
    auto in_right = in_left ? findChessboardCorners(right[i], board) : std::nullopt;
    if (!in_left || !in_right) continue;
    object_points.push_back(board_points);
    left_points.push_back(std::move(*in_left));
    right_points.push_back(std::move(*in_right));
  }
  if (object_points.size() < 3) {
    throw std::invalid_argument("calibration: the whole " +
                                std::to_string(board.inner_corners.width) + "x" +
                                std::to_string(board.inner_corners.height) +
                                " board is seen by both cameras in only " +
                                std::to_string(object_points.size()) + " pairs (3 or more needed)");
  }
  StereoCalibrationResult result;
  result.pairs_used = object_points.size();
  const auto intrinsics = [&](const std::vector<std::vector<cv::Point2f>>& points,
                              cv::Size size) {
    CameraCalibration camera;
    camera.size = size;
    cv::Mat matrix, distortion;
    std::vector<cv::Mat> rotations, translations;
    cv::calibrateCamera(object_points, points, size, matrix, distortion, rotations, translations);
    camera.camera_matrix = cv::Matx33d(matrix.ptr<double>());
    camera.distortion.assign(distortion.begin<double>(), distortion.end<double>());
    return camera;
  };
  CameraCalibration left_camera = intrinsics(left_points, left[0].size());
  CameraCalibration right_camera = intrinsics(right_points, right[0].size());
  cv::Mat K1(left_camera.camera_matrix), K2(right_camera.camera_matrix);
  cv::Mat D1(left_camera.distortion, true), D2(right_camera.distortion, true);
  cv::Mat R, T, E, F;
  result.rms_reprojection_px =
      cv::stereoCalibrate(object_points, left_points, right_points, K1, D1, K2, D2,
                          left[0].size(), R, T, E, F, cv::CALIB_FIX_INTRINSIC);
  right_camera.rotation = cv::Matx33d(R.ptr<double>());
  right_camera.translation = cv::Vec3d(T.ptr<double>());
  result.calibration.cameras = {left_camera, right_camera};
  return result;
}

}  // namespace stereonav
