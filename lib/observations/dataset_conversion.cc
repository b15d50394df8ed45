#include "observations/dataset_conversion.h"

#include <mrpt/obs/CObservationStereoImages.h>
#include <mrpt/poses/CPose3DQuat.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <sstream>

#include "common/image_file.h"
#include "rectification/calibration_files.h"

namespace stereonav {
namespace {

namespace fs = std::filesystem;


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
    pair.imageLeft = mrpt::img::CImage(readImageFile(left, cv::IMREAD_GRAYSCALE), mrpt::img::DEEP_COPY);
    pair.imageRight = mrpt::img::CImage(readImageFile(right, cv::IMREAD_GRAYSCALE), mrpt::img::DEEP_COPY);
    pair.hasImageRight = true;
    writer.write(std::move(observations), std::nullopt);
    ++frames;
    if (on_frame) on_frame(frames);
  }
  if (frames == 0) throw std::runtime_error(dataset + ": no image pair listed in cam0/data.csv");
  return frames;
}

size_t convertKitti(const KittiSequence& sequence, const OdometryError& error, RawlogWriter& writer,
                    const std::function<void(size_t)>& on_frame) {
  const std::vector<mrpt::poses::CPose2D> odometry = odometryWithError(sequence.poses, error);
  for (size_t i = 0; i < sequence.frames; ++i) {
    writer.write(kittiFrame(sequence, i, i < odometry.size() ? std::optional(odometry[i]) : std::nullopt));
    if (on_frame) on_frame(i + 1);
  }
  return sequence.frames;
}

}  // namespace stereonav
