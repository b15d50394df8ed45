#include <opencv2/core/utility.hpp>
#include <opencv2/imgcodecs.hpp>

#include <iostream>

#include "command_line.h"
#include "commands.h"
#include "common/image_file.h"
#include "rectification/calibration_files.h"
#include "rectification/chessboard_calibration.h"
#include "rectification/stereo_rectifier.h"

namespace stereonav::app {
namespace {

constexpr const char* kUsage =
    "usage: stereonav calibrate --left 'DIR/left*.jpg' --right 'DIR/right*.jpg' --out CALIB.yaml\n"
    "                           [--board 9x6] [--square 0.025]\n"
    "Calibrates a stereo pair from chessboard views (quote the patterns: they are matched here and\n"
    "paired in sorted order). --board: inner corners per row x per column; --square: side in\n"
    "metres. Writes OpenCV YAML (M1 D1 M2 D2 R T, image size) that [rawlog] calibration reads;\n"
    "the left camera is the reference.\n";

std::vector<cv::Mat> readImages(const std::string& pattern, const std::string& option,
                                std::vector<std::string>& paths) {
  cv::glob(pattern, paths, false);
  if (paths.empty()) throw UsageError(option + " '" + pattern + "': no file matches");
  std::vector<cv::Mat> images;
  for (const std::string& path : paths) {
    images.push_back(readImageFile(path, cv::IMREAD_GRAYSCALE));
  }
  return images;
}

}  // namespace

int runCalibrateCommand(const std::vector<std::string>& arguments) {
  CommandLine command_line(arguments, {"help"});
  if (command_line.flag("help")) {
    std::cout << kUsage;
    return 0;
  }
  const std::string left_pattern = command_line.required("left");
  const std::string right_pattern = command_line.required("right");
  const std::string out = command_line.required("out");
  const std::string board_text = command_line.value("board").value_or("9x6");
  const auto square = command_line.doubleValue("square");
  command_line.rejectUnknown();

  Chessboard board;
  char separator = 0, rest = 0;
  if (std::sscanf(board_text.c_str(), "%d%c%d%c", &board.inner_corners.width, &separator,
                  &board.inner_corners.height, &rest) != 3 ||
      separator != 'x' || board.inner_corners.width < 2 || board.inner_corners.height < 2) {
    throw UsageError("--board '" + board_text + "': expected COLUMNSxROWS of inner corners, e.g. 9x6");
  }
  if (square) {
    if (!(*square > 0)) throw UsageError("--square must be positive");
    board.square_m = *square;
  }
  std::vector<std::string> left_paths, right_paths;
  const auto left = readImages(left_pattern, "--left", left_paths);
  const auto right = readImages(right_pattern, "--right", right_paths);
  if (left.size() != right.size()) {
    throw UsageError("--left matches " + std::to_string(left.size()) + " files, --right " +
                     std::to_string(right.size()));
  }
  const StereoCalibrationResult result = calibrateStereo(left, right, board);
  StereoRectifier rectifier(result.calibration);  // refuses a calibration it cannot use
  saveRigCalibration(result.calibration, out);
  const CameraRig& rig = rectifier.rig();
  std::cout << "calibrate: " << result.pairs_used << " of " << left.size()
            << " pairs show the whole board; rms reprojection error "
            << result.rms_reprojection_px << " px\n"
            << "calibrate: rectified rig: f " << rig.reference.focal_px << " px, baseline "
            << rig.baseline_m << " m (in the units of --square)\n"
            << "calibrate: wrote " << out << "\n";
  return 0;
}

}  // namespace stereonav::app
