#include "observations/kitti_sequence.h"

#include <mrpt/system/datetime.h>

#include <opencv2/imgcodecs.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace stereonav {
namespace {

constexpr double kFrameRateHz = 10.0;

std::vector<std::vector<double>> readRows(const std::string& path, size_t fields) {
  std::ifstream file(path);
  if (!file) throw std::runtime_error(path + ": cannot read");
  std::vector<std::vector<double>> rows;
  std::string line;
  for (int number = 1; std::getline(file, line); ++number) {
    std::istringstream text(line);
    std::string label;
    // calib.txt may label its lines ("P0: ..."); poses.txt does not.
    if (line.find(':') != std::string::npos) text >> label;
    std::vector<double> row;
    for (double value; text >> value;) row.push_back(value);
    if (row.empty()) continue;
    if (row.size() != fields) {
      throw std::runtime_error(path + ":" + std::to_string(number) + ": expected " +
                               std::to_string(fields) + " numbers");
    }
    rows.push_back(row);
  }
  return rows;
}

std::string imagePath(const std::string& directory, const char* camera, size_t index) {
  char name[32];
  std::snprintf(name, sizeof name, "/%s/%06zu.png", camera, index);
  return directory + name;
}

}  // namespace

KittiSequence loadKittiSequence(const std::string& directory, double camera_height_m) {
  KittiSequence sequence;
  sequence.directory = directory;
  const auto calibration = readRows(directory + "/calib.txt", 12);
  if (calibration.size() < 2) throw std::runtime_error(directory + "/calib.txt: expected two cameras");
  const std::vector<double>& left = calibration[0];
  const std::vector<double>& right = calibration[1];
  const cv::Mat first = cv::imread(imagePath(directory, "image_l", 0), cv::IMREAD_GRAYSCALE);
  if (first.empty()) throw std::runtime_error(imagePath(directory, "image_l", 0) + ": cannot read");
  CameraRig& rig = sequence.rig;
  rig.reference = {first.cols, first.rows, left[0], left[2], left[6]};
  // The right projection's fourth entry is -f B (KITTI's convention).
  rig.baseline_m = -right[3] / right[0];
  if (!(rig.baseline_m > 0.0)) throw std::runtime_error(directory + "/calib.txt: no positive baseline");
  rig.secondaries = {{1.0, 0.0}};
  rig.pose_on_robot = CameraRig::opticalPoseOnRobot(0.0, 0.0, camera_height_m, 0.0, 0.0);

  for (const std::vector<double>& pose : readRows(directory + "/poses.txt", 12)) {
    // Camera x right, y down, z forward -> robot x forward (z), y left (-x); the heading is that
    // of the optical axis (the rotation's third column) on the floor.
    sequence.poses.emplace_back(pose[11], -pose[3], std::atan2(-pose[2], pose[10]));
  }
  return sequence;
}

RigFrame kittiFrame(const KittiSequence& sequence, size_t index,
                    const mrpt::poses::CPose2D& odometry) {
  RigFrame frame;
  frame.timestamp = mrpt::Clock::fromDouble(static_cast<double>(index) / kFrameRateHz);
  frame.rig = sequence.rig;
  frame.reference = cv::imread(imagePath(sequence.directory, "image_l", index), cv::IMREAD_GRAYSCALE);
  const cv::Mat right = cv::imread(imagePath(sequence.directory, "image_r", index), cv::IMREAD_GRAYSCALE);
  if (frame.reference.empty() || right.empty()) {
    throw std::runtime_error(imagePath(sequence.directory, frame.reference.empty() ? "image_l" : "image_r", index) +
                             ": cannot read");
  }
  frame.secondaries = {right};
  frame.odometry = odometry;
  return frame;
}

}  // namespace stereonav
