#include "observations/kitti_sequence.h"

#include <mrpt/core/bits_math.h>
#include <mrpt/system/datetime.h>

#include <opencv2/imgcodecs.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <stdexcept>

#include "common/image_file.h"

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

std::string imagePath(const std::string& directory, size_t index) {
  char name[32];
  std::snprintf(name, sizeof name, "/%06zu.png", index);
  return directory + name;
}

}  // namespace

KittiSequence loadKittiSequence(const std::string& directory, double camera_height_m) {
  KittiSequence sequence;
  const auto calibration = readRows(directory + "/calib.txt", 12);
  if (calibration.size() < 2) throw std::runtime_error(directory + "/calib.txt: expected two cameras");
  const std::vector<double>& left = calibration[0];
  const std::vector<double>& right = calibration[1];
  const bool kitti_names = !std::filesystem::is_directory(directory + "/image_l");
  sequence.left_directory = directory + (kitti_names ? "/image_0" : "/image_l");
  sequence.right_directory = directory + (kitti_names ? "/image_1" : "/image_r");
  const cv::Mat first = readImageFile(imagePath(sequence.left_directory, 0), cv::IMREAD_GRAYSCALE);
  while (std::filesystem::exists(imagePath(sequence.left_directory, sequence.frames))) ++sequence.frames;
  CameraRig& rig = sequence.rig;
  rig.reference = {first.cols, first.rows, left[0], left[2], left[6]};
  // The right projection's fourth entry is -f B (KITTI's convention).
  rig.baseline_m = -right[3] / right[0];
  if (!(rig.baseline_m > 0.0)) throw std::runtime_error(directory + "/calib.txt: no positive baseline");
  rig.secondaries = {{1.0, 0.0}};
  rig.pose_on_robot = CameraRig::opticalPoseOnRobot(0.0, 0.0, camera_height_m, 0.0, 0.0);

  const std::string poses_path = directory + "/poses.txt";
  if (!std::filesystem::exists(poses_path)) return sequence;
  for (const std::vector<double>& pose : readRows(poses_path, 12)) {
    // Camera x right, y down, z forward -> robot x forward (z), y left (-x); the heading is that
    // of the optical axis (the rotation's third column) on the floor.
    sequence.poses.emplace_back(pose[11], -pose[3], std::atan2(-pose[2], pose[10]));
  }
  return sequence;
}

RigFrame kittiFrame(const KittiSequence& sequence, size_t index,
                    const std::optional<mrpt::poses::CPose2D>& odometry) {
  RigFrame frame;
  frame.timestamp = mrpt::Clock::fromDouble(static_cast<double>(index) / kFrameRateHz);
  frame.rig = sequence.rig;
  const std::string left_path = imagePath(sequence.left_directory, index);
  const std::string right_path = imagePath(sequence.right_directory, index);
  frame.reference = readImageFile(left_path, cv::IMREAD_GRAYSCALE);
  frame.secondaries = {readImageFile(right_path, cv::IMREAD_GRAYSCALE)};
  frame.odometry = odometry;
  return frame;
}

std::vector<mrpt::poses::CPose2D> odometryWithError(const std::vector<mrpt::poses::CPose2D>& truth,
                                                    const OdometryError& error) {
  std::vector<mrpt::poses::CPose2D> odometry;
  if (truth.empty()) return odometry;
  std::mt19937 random(error.seed);
  std::normal_distribution<double> unit(0.0, 1.0);
  odometry.push_back(truth.front());
  for (size_t i = 1; i < truth.size(); ++i) {
    const mrpt::poses::CPose2D step = truth[i] - truth[i - 1];
    const double distance = step.norm();
    odometry.push_back(odometry.back() +
                       mrpt::poses::CPose2D(step.x() * (1.0 + error.distance_bias),
                                            step.y() * (1.0 + error.distance_bias),
                                            step.phi() + mrpt::DEG2RAD(error.drift_deg_per_m) * distance *
                                                             unit(random)));
  }
  return odometry;
}

}  // namespace stereonav
