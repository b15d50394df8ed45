#include "rectification/calibration_files.h"

#include <mrpt/img/TStereoCamera.h>
#include <mrpt/poses/CPose3DQuat.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <opencv2/core/persistence.hpp>
#include <set>

#include "common/atomic_file.h"
#include "common/ini_section.h"

namespace stereonav {
namespace {

cv::Matx33d toMatx(const mrpt::math::CMatrixDouble33& m) {
  cv::Matx33d out;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) out(r, c) = m(r, c);
  }
  return out;
}

bool endsWith(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() &&
         text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// The files of one calibration, each opened with OpenCV's FileStorage; a key is looked up in the
// first file that has it (stereo_calib splits intrinsics and extrinsics into two files).
class CalibrationNodes {
 public:
  explicit CalibrationNodes(const std::vector<std::string>& paths) : paths_(paths) {
    for (const std::string& path : paths_) {
      std::ifstream file(path);
      if (!file) throw RectificationError(path + ": cannot read calibration file");
      std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
      // OpenCV wants its "%YAML:1.0" header, which ROS camera_info files do not have.
      if (text.rfind("%YAML", 0) != 0 && text.rfind("<?xml", 0) != 0) text = "%YAML:1.0\n" + text;
      cv::FileStorage storage;
      try {
        storage.open(text, cv::FileStorage::READ | cv::FileStorage::MEMORY);
      } catch (const cv::Exception& e) {
        throw RectificationError(path + ": not an OpenCV YAML/XML calibration (" + e.err + ")");
      }
      if (!storage.isOpened()) throw RectificationError(path + ": not a YAML/XML file");
      files_.push_back(std::move(storage));
    }
  }

  size_t size() const { return files_.size(); }
  const std::string& path(size_t file) const { return paths_[file]; }
  bool has(size_t file, const std::string& key) const { return !files_[file][key].empty(); }
  bool hasAnywhere(const std::string& key) const {
    for (size_t f = 0; f < files_.size(); ++f) {
      if (has(f, key)) return true;
    }
    return false;
  }

  // A matrix stored as an OpenCV !!opencv-matrix or as ROS/EuRoC's {rows, cols, data}.
  cv::Mat matrix(size_t file, const std::string& key, int rows, int cols) const {
    const cv::FileNode node = files_[file][key];
    if (node.empty()) throw RectificationError(paths_[file] + ": no '" + key + "'");
    cv::Mat matrix;
    if (node.isMap() && !node["data"].empty()) {
      std::vector<double> data;
      node["data"] >> data;
      matrix = cv::Mat(data, true);
    } else if (node.isSeq()) {
      std::vector<double> data;
      node >> data;
      matrix = cv::Mat(data, true);
    } else {
      node >> matrix;
      matrix.convertTo(matrix, CV_64F);
    }
    if (rows > 0 && static_cast<int>(matrix.total()) != rows * cols) {
      throw RectificationError(paths_[file] + ": '" + key + "' has " +
                               std::to_string(matrix.total()) + " numbers, expected " +
                               std::to_string(rows * cols));
    }
    return rows > 0 ? matrix.reshape(1, rows) : matrix.reshape(1, 1);
  }
  cv::Mat matrixAnywhere(const std::string& key, int rows, int cols) const {
    for (size_t f = 0; f < files_.size(); ++f) {
      if (has(f, key)) return matrix(f, key, rows, cols);
    }
    throw RectificationError(paths_.front() + (paths_.size() > 1 ? " (and the other files)" : "") +
                             ": no '" + key + "'");
  }
  int integer(size_t file, const std::string& key) const {
    return static_cast<int>(files_[file][key].real());
  }
  std::string text(size_t file, const std::string& key) const {
    return files_[file][key].empty() ? "" : files_[file][key].string();
  }

 private:
  std::vector<std::string> paths_;
  std::vector<cv::FileStorage> files_;
};

cv::Matx33d matx33(const cv::Mat& m) { return cv::Matx33d(m.ptr<double>()); }
cv::Vec3d vec3(const cv::Mat& m) { return cv::Vec3d(m.ptr<double>()); }
std::vector<double> coefficients(const cv::Mat& m) { return std::vector<double>(m.begin<double>(), m.end<double>()); }

// OpenCV stereo_calib (M1 D1 M2 D2 R T) or 3calibration (cameraMatrixK distCoeffsK R1K T1K).
RigCalibration loadOpenCvStereo(const CalibrationNodes& nodes) {
  RigCalibration calibration;
  const bool pair_names = nodes.hasAnywhere("M1");
  const int cameras = pair_names ? 2 : (nodes.hasAnywhere("cameraMatrix3") ? 3 : 2);
  for (int k = 1; k <= cameras; ++k) {
    const std::string n = std::to_string(k);
    CameraCalibration camera;
    camera.camera_matrix = matx33(nodes.matrixAnywhere((pair_names ? "M" : "cameraMatrix") + n, 3, 3));
    camera.distortion = coefficients(nodes.matrixAnywhere((pair_names ? "D" : "distCoeffs") + n, 0, 0));
    if (k > 1) {
      const std::string pose = pair_names ? "" : "1" + n;
      camera.rotation = matx33(nodes.matrixAnywhere("R" + pose, 3, 3));
      camera.translation = vec3(nodes.matrixAnywhere("T" + pose, 3, 1));
    }
    for (size_t f = 0; f < nodes.size(); ++f) {
      if (nodes.has(f, "image_width")) {
        camera.size = {nodes.integer(f, "image_width"), nodes.integer(f, "image_height")};
      }
    }
    calibration.cameras.push_back(camera);
  }
  return calibration;
}

// ROS camera_info: each camera's raw frame -> common rectified frame (rectification_matrix), and
// its place there from the projection matrix: P = K' [I | -c] gives c = -(P03 / fx', P13 / fy').
RigCalibration loadRosCameraInfo(const CalibrationNodes& nodes) {
  RigCalibration calibration;
  std::vector<cv::Matx33d> to_rectified;
  std::vector<cv::Vec3d> rectified_centres;
  for (size_t f = 0; f < nodes.size(); ++f) {
    CameraCalibration camera;
    camera.size = {nodes.integer(f, "image_width"), nodes.integer(f, "image_height")};
    camera.camera_matrix = matx33(nodes.matrix(f, "camera_matrix", 3, 3));
    const std::string model = nodes.text(f, "distortion_model");
    if (model != "plumb_bob" && model != "rational_polynomial" && !model.empty()) {
      throw RectificationError(nodes.path(f) + ": distortion_model '" + model +
                               "' is not supported (plumb_bob or rational_polynomial)");
    }
    if (nodes.has(f, "distortion_coefficients")) {
      camera.distortion = coefficients(nodes.matrix(f, "distortion_coefficients", 0, 0));
    }
    to_rectified.push_back(nodes.has(f, "rectification_matrix")
                               ? matx33(nodes.matrix(f, "rectification_matrix", 3, 3))
                               : cv::Matx33d::eye());
    const cv::Mat projection = nodes.matrix(f, "projection_matrix", 3, 4);
    rectified_centres.push_back({-projection.at<double>(0, 3) / projection.at<double>(0, 0),
                                 -projection.at<double>(1, 3) / projection.at<double>(1, 1), 0.0});
    calibration.cameras.push_back(camera);
  }
  for (size_t k = 0; k < calibration.cameras.size(); ++k) {
    CameraCalibration& camera = calibration.cameras[k];
    camera.rotation = to_rectified[k].t() * to_rectified[0];
    camera.translation = -(to_rectified[k].t() * (rectified_centres[k] - rectified_centres[0]));
  }
  return calibration;
}

// EuRoC: T_BS of each camera in the body frame; X_k = inv(T_BS_k) T_BS_0 X_0.
RigCalibration loadEurocSensors(const CalibrationNodes& nodes) {
  RigCalibration calibration;
  std::vector<cv::Matx44d> body_from_sensor;
  for (size_t f = 0; f < nodes.size(); ++f) {
    CameraCalibration camera;
    const cv::Mat resolution = nodes.matrix(f, "resolution", 1, 2);
    camera.size = {static_cast<int>(resolution.at<double>(0)),
                   static_cast<int>(resolution.at<double>(1))};
    const cv::Mat intrinsics = nodes.matrix(f, "intrinsics", 1, 4);
    const double* q = intrinsics.ptr<double>();
    camera.camera_matrix = cv::Matx33d(q[0], 0, q[2], 0, q[1], q[3], 0, 0, 1);
    const std::string model = nodes.text(f, "distortion_model");
    if (model != "radial-tangential") {
      throw RectificationError(nodes.path(f) + ": distortion_model '" + model +
                               "' is not supported (radial-tangential)");
    }
    camera.distortion = coefficients(nodes.matrix(f, "distortion_coefficients", 0, 0));
    body_from_sensor.push_back(cv::Matx44d(nodes.matrix(f, "T_BS", 4, 4).ptr<double>()));
    calibration.cameras.push_back(camera);
  }
  for (size_t k = 0; k < calibration.cameras.size(); ++k) {
    const cv::Matx44d relative = body_from_sensor[k].inv() * body_from_sensor[0];
    calibration.cameras[k].rotation = relative.get_minor<3, 3>(0, 0);
    calibration.cameras[k].translation = {relative(0, 3), relative(1, 3), relative(2, 3)};
  }
  return calibration;
}

RigCalibration loadMrptStereoCamera(const std::string& path) {
  const mrpt::config::CConfigFileMemory config = readConfigFile(path);
  std::vector<std::string> sections;
  config.getAllSections(sections);
  std::string prefix;
  for (const std::string& section : sections) {
    if (endsWith(section, "_LEFT2RIGHT_POSE")) prefix = section.substr(0, section.size() - 16);
  }
  if (prefix.empty()) {
    throw RectificationError(path + ": no [<name>_LEFT2RIGHT_POSE] section of an MRPT TStereoCamera");
  }
  mrpt::img::TStereoCamera stereo;
  try {
    stereo.loadFromConfigFile(prefix, config);
  } catch (const std::exception& e) {
    const std::string what = e.what();
    throw RectificationError(path + ": [" + prefix + "_*]: " + what.substr(0, what.find('\n')));
  }
  RigCalibration calibration;
  calibration.cameras = {cameraCalibrationOf(stereo.leftCamera),
                         cameraCalibrationOf(stereo.rightCamera)};
  placeCamera(calibration.cameras[1],
              mrpt::poses::CPose3D(mrpt::poses::CPose3DQuat(stereo.rightCameraPose)));
  return calibration;
}

void requireValid(const RigCalibration& calibration, const std::vector<std::string>& paths) {
  RigCalibration sized = calibration;
  for (auto& camera : sized.cameras) {
    if (camera.size.area() == 0) camera.size = {1, 1};  // supplied by the images later
  }
  try {
    checkRigCalibration(sized);
  } catch (const RectificationError& e) {
    throw RectificationError(paths.front() + ": " + e.what());
  }
}

}  // namespace

CameraCalibration cameraCalibrationOf(const mrpt::img::TCamera& camera) {
  CameraCalibration calibration;
  calibration.size = {static_cast<int>(camera.ncols), static_cast<int>(camera.nrows)};
  calibration.camera_matrix = toMatx(camera.intrinsicParams);
  switch (camera.distortion) {
    case mrpt::img::DistortionModel::none:
      break;
    case mrpt::img::DistortionModel::plumb_bob:
      calibration.distortion.assign(camera.dist.begin(), camera.dist.end());
      break;
    default:
      throw RectificationError(camera.cameraName +
                               ": fisheye (kannala_brandt) distortion is not supported");
  }
  return calibration;
}

void placeCamera(CameraCalibration& camera, const mrpt::poses::CPose3D& pose) {
  const cv::Matx33d rotation = toMatx(pose.getRotationMatrix());
  camera.rotation = rotation.t();
  camera.translation = -(rotation.t() * cv::Vec3d(pose.x(), pose.y(), pose.z()));
}

mrpt::img::TCamera tcameraOf(const CameraCalibration& camera, const std::string& name) {
  mrpt::img::TCamera t;
  t.ncols = static_cast<uint32_t>(camera.size.width);
  t.nrows = static_cast<uint32_t>(camera.size.height);
  const cv::Matx33d& K = camera.camera_matrix;
  t.setIntrinsicParamsFromValues(K(0, 0), K(1, 1), K(0, 2), K(1, 2));
  std::vector<double> d = camera.distortion;
  d.resize(5, 0.0);
  t.setDistortionPlumbBob(d[0], d[1], d[2], d[3], d[4]);
  t.cameraName = name;
  return t;
}

mrpt::poses::CPose3D poseInReference(const CameraCalibration& camera) {
  const cv::Matx33d to_reference = camera.rotation.t();
  const cv::Vec3d centre = camera.centreInReference();
  mrpt::math::CMatrixDouble33 rotation;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) rotation(r, c) = to_reference(r, c);
  }
  return mrpt::poses::CPose3D(rotation,
                              mrpt::math::CVectorFixedDouble<3>({centre[0], centre[1], centre[2]}));
}

RigCalibration loadRigCalibration(const std::vector<std::string>& paths) {
  if (paths.empty()) throw RectificationError("no calibration file given");
  RigCalibration calibration;
  if (endsWith(paths.front(), ".ini") || endsWith(paths.front(), ".cfg")) {
    if (paths.size() != 1) throw RectificationError(paths[1] + ": an MRPT calibration is one file");
    if (!std::ifstream(paths.front())) {
      throw RectificationError(paths.front() + ": cannot read calibration file");
    }
    calibration = loadMrptStereoCamera(paths.front());
  } else {
    const CalibrationNodes nodes(paths);
    if (nodes.has(0, "camera_matrix")) {
      calibration = loadRosCameraInfo(nodes);
    } else if (nodes.has(0, "T_BS")) {
      calibration = loadEurocSensors(nodes);
    } else if (nodes.hasAnywhere("M1") || nodes.hasAnywhere("cameraMatrix1")) {
      calibration = loadOpenCvStereo(nodes);
    } else {
      throw RectificationError(paths.front() +
                               ": not a calibration this program reads (OpenCV M1/D1/M2/D2/R/T, "
                               "ROS camera_info, EuRoC sensor.yaml or MRPT TStereoCamera ini)");
    }
  }
  requireValid(calibration, paths);
  return calibration;
}

void saveRigCalibration(const RigCalibration& calibration, const std::string& path) {
  checkRigCalibration(calibration);
  const size_t n = calibration.cameras.size();
  if (n > 3) throw RectificationError(path + ": only heads of two or three cameras can be saved");
  writeFileAtomically(path, [&](const std::string& temporary) {
    cv::FileStorage storage(temporary, cv::FileStorage::WRITE | cv::FileStorage::FORMAT_YAML);
    if (!storage.isOpened()) throw std::runtime_error(path + ": cannot write");
    const CameraCalibration& reference = calibration.cameras[0];
    storage << "image_width" << reference.size.width << "image_height" << reference.size.height;
    for (size_t k = 0; k < n; ++k) {
      const CameraCalibration& camera = calibration.cameras[k];
      const std::string i = std::to_string(k + 1);
      const bool pair = n == 2;
      storage << (pair ? "M" : "cameraMatrix") + i << cv::Mat(camera.camera_matrix);
      storage << (pair ? "D" : "distCoeffs") + i << cv::Mat(camera.distortion, true).reshape(1, 1);
      if (k > 0) {
        storage << "R" + (pair ? std::string() : "1" + i) << cv::Mat(camera.rotation);
        storage << "T" + (pair ? std::string() : "1" + i) << cv::Mat(camera.translation);
      }
    }
  });
}

RigCalibration withImageSizes(RigCalibration calibration, const std::vector<cv::Size>& sizes) {
  if (sizes.size() != calibration.cameras.size()) {
    throw RectificationError("the calibration has " + std::to_string(calibration.cameras.size()) +
                             " cameras, the frame " + std::to_string(sizes.size()) + " images");
  }
  for (size_t k = 0; k < sizes.size(); ++k) {
    cv::Size& size = calibration.cameras[k].size;
    if (size.area() == 0) size = sizes[k];
    if (size != sizes[k]) {
      throw RectificationError("camera " + std::to_string(k) + ": image is " +
                               std::to_string(sizes[k].width) + "x" + std::to_string(sizes[k].height) +
                               ", its calibration is for " + std::to_string(size.width) + "x" +
                               std::to_string(size.height));
    }
  }
  return calibration;
}

RigCalibration withReference(const RigCalibration& calibration, size_t reference) {
  RigCalibration result = calibration;
  if (reference == 0) return result;
  const CameraCalibration& new_reference = calibration.cameras.at(reference);
  for (auto& camera : result.cameras) {
    // X_k = R_k X_0 + T_k and X_0 = R_r^T (X_r - T_r).
    const cv::Matx33d rotation = camera.rotation * new_reference.rotation.t();
    camera.translation = camera.translation - rotation * new_reference.translation;
    camera.rotation = rotation;
  }
  std::swap(result.cameras[0], result.cameras[reference]);
  return result;
}

}  // namespace stereonav
