#include "observations/dataset_conversion.h"

#include <mrpt/obs/CObservationStereoImages.h>
#include <mrpt/poses/CPose3DQuat.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <sstream>

#include "rectification/calibration_files.h"

namespace stereonav {
namespace {

namespace fs = std::filesystem;

cv::Mat readGrey(const std::string& path) {
  if (!fs::is_regular_file(path)) throw std::runtime_error(path + ": no such image");
  cv::Mat image = cv::imread(path, cv::IMREAD_GRAYSCALE);
  if (image.empty()) throw std::runtime_error(path + ": cannot read image");
  return image;
}

std::vector<double> numbersOf(const std::string& line) {
  std::istringstream fields(line);
  std::vector<double> numbers;
  std::string field;
  while (fields >> field) {
    try {
      numbers.push_back(std::stod(field));
    } catch (const std::logic_error&) {
      // a "P0:" key in front of the numbers
    }
  }
  return numbers;
}

}  // namespace

size_t convertEuroc(const std::string& dataset, RawlogWriter& writer,
                    const std::function<void(size_t)>& on_frame) {
  RigCalibration calibration;
  try {
    calibration = loadRigCalibration({dataset + "/cam0/sensor.yaml", dataset + "/cam1/sensor.yaml"});
  } catch (const RectificationError& e) {
    throw std::runtime_error(e.what());
  }
  const std::string index_path = dataset + "/cam0/data.csv";
  std::ifstream index(index_path);
  if (!index) throw std::runtime_error(index_path + ": cannot read");
  const auto left_camera = tcameraOf(calibration.cameras[0], "EUROC_CAM0");
  const auto right_camera = tcameraOf(calibration.cameras[1], "EUROC_CAM1");
  const mrpt::poses::CPose3DQuat right_pose(poseInReference(calibration.cameras[1]));
  const mrpt::poses::CPose3DQuat mount(CameraRig::opticalPoseOnRobot(0, 0, 1.0, 0, 0));
  size_t frames = 0;
  std::string line;
  for (int number = 1; std::getline(index, line); ++number) {
    if (line.empty() || line[0] == '#') continue;
    const size_t comma = line.find(',');
    std::string file = comma == std::string::npos ? "" : line.substr(comma + 1);
    while (!file.empty() && std::isspace(static_cast<unsigned char>(file.back()))) file.pop_back();
    int64_t nanoseconds = 0;
    try {
      nanoseconds = std::stoll(line.substr(0, comma));
    } catch (const std::logic_error&) {
      throw std::runtime_error(index_path + ":" + std::to_string(number) +
                               ": expected 'timestamp_ns,file'");
    }
    const std::string left = dataset + "/cam0/data/" + file, right = dataset + "/cam1/data/" + file;
    if (file.empty() || !fs::exists(left) || !fs::exists(right)) continue;
    RigObservations observations;
    observations.pair = mrpt::obs::CObservationStereoImages::Create();
    auto& pair = *observations.pair;
    pair.sensorLabel = writer.sensorLabel();
    pair.timestamp = mrpt::Clock::fromDouble(static_cast<double>(nanoseconds) * 1e-9);
    pair.leftCamera = left_camera;
    pair.rightCamera = right_camera;
    pair.cameraPose = mount;
    pair.rightCameraPose = right_pose;
    pair.imageLeft = mrpt::img::CImage(readGrey(left), mrpt::img::DEEP_COPY);
    pair.imageRight = mrpt::img::CImage(readGrey(right), mrpt::img::DEEP_COPY);
    pair.hasImageRight = true;
    writer.write(std::move(observations), std::nullopt);
    ++frames;
    if (on_frame) on_frame(frames);
  }
  if (frames == 0) throw std::runtime_error(dataset + ": no image pair listed in cam0/data.csv");
  return frames;
}

size_t convertKitti(const std::string& dataset, RawlogWriter& writer,
                    const std::function<void(size_t)>& on_frame) {
  const std::string calib_path = dataset + "/calib.txt";
  std::ifstream calib(calib_path);
  if (!calib) throw std::runtime_error(calib_path + ": cannot read");
  std::vector<std::vector<double>> projections;
  for (std::string line; std::getline(calib, line) && projections.size() < 2;) {
    std::vector<double> numbers = numbersOf(line);
    if (numbers.size() >= 12) projections.push_back(numbers);
  }
  if (projections.size() < 2 || !(projections[0][0] > 0)) {
    throw std::runtime_error(calib_path + ": expected two 3x4 projection matrices (left, right)");
  }
  const double baseline = (projections[0][3] - projections[1][3]) / projections[0][0];
  if (!(baseline > 0)) throw std::runtime_error(calib_path + ": right camera not to the right");
  const PinholeCamera camera{0, 0, projections[0][0], projections[0][2], projections[0][6]};
  const CameraRig rig{camera, baseline, {SecondaryCamera{1.0, 0.0}},
                      CameraRig::opticalPoseOnRobot(0, 0, 1.65, 0, 0)};

  std::string left_dir = dataset + "/image_l", right_dir = dataset + "/image_r";
  if (!fs::is_directory(left_dir)) left_dir = dataset + "/image_0", right_dir = dataset + "/image_1";
  std::ifstream poses(dataset + "/poses.txt");
  size_t frames = 0;
  for (;; ++frames) {
    char name[16];
    std::snprintf(name, sizeof name, "/%06zu.png", frames);
    if (!fs::exists(left_dir + name)) break;
    RigFrame frame{mrpt::Clock::fromDouble(0.1 * static_cast<double>(frames)),
                   readGrey(left_dir + name), {readGrey(right_dir + name)}, rig, std::nullopt};
    frame.rig.reference.width = frame.reference.cols;
    frame.rig.reference.height = frame.reference.rows;
    std::string line;
    if (poses && std::getline(poses, line)) {
      const std::vector<double> m = numbersOf(line);
      if (m.size() != 12) {
        throw std::runtime_error(dataset + "/poses.txt:" + std::to_string(frames + 1) +
                                 ": expected 12 numbers");
      }
      // Camera x right, z forward -> robot x forward, y left; heading = the camera's z axis.
      frame.odometry = mrpt::poses::CPose2D(m[11], -m[3], std::atan2(-m[2], m[10]));
    }
    writer.write(frame);
    if (on_frame) on_frame(frames + 1);
  }
  if (frames == 0) throw std::runtime_error(left_dir + ": no 000000.png");
  return frames;
}

}  // namespace stereonav
