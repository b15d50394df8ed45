#include "rectification/calibration_files.h"

#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/img/TStereoCamera.h>
#include <mrpt/poses/CPose3DQuat.h>

#include <filesystem>
#include <fstream>
#include <opencv2/calib3d.hpp>

#include "synthetic_heads.h"
#include "support/scratch_directory.h"

namespace stereonav {
namespace {

class CalibrationFilesTest : public ::testing::Test {
 protected:
  std::string file(const std::string& name, const std::string& text = "") const {
    const std::string path = scratch_.file(name);
    if (!text.empty()) std::ofstream(path) << text;
    return path;
  }

 private:
  test_support::ScratchDirectory scratch_;
};

void expectSameCamera(const CameraCalibration& a, const CameraCalibration& b, double tolerance) {
  EXPECT_EQ(a.size, b.size);
  EXPECT_LT(cv::norm(a.camera_matrix - b.camera_matrix, cv::NORM_INF), tolerance);
  EXPECT_LT(cv::norm(a.rotation - b.rotation, cv::NORM_INF), tolerance);
  EXPECT_LT(cv::norm(a.translation - b.translation, cv::NORM_INF), tolerance);
  std::vector<double> da = a.distortion, db = b.distortion;
  da.resize(8, 0.0), db.resize(8, 0.0);
  for (size_t i = 0; i < 8; ++i) EXPECT_NEAR(da[i], db[i], tolerance) << "coefficient " << i;
}

TEST_F(CalibrationFilesTest, OpenCvFormatRoundTripsForTwoAndThreeCameras) {
  for (const RigCalibration& head : {rawBinocularHead(), rawLShapedHead()}) {
    const std::string path = file("head.yaml");
    saveRigCalibration(head, path);
    const RigCalibration loaded = loadRigCalibration({path});
    ASSERT_EQ(loaded.cameras.size(), head.cameras.size());
    for (size_t k = 0; k < head.cameras.size(); ++k) {
      expectSameCamera(loaded.cameras[k], head.cameras[k], 1e-12);
    }
  }
}

TEST_F(CalibrationFilesTest, OpenCvStereoCalibSplitFilesWithoutImageSize) {
  // What OpenCV's stereo_calib sample writes: intrinsics.yml and extrinsics.yml, no image size.
  const RigCalibration head = rawBinocularHead();
  const std::string intrinsics = file("intrinsics.yml"), extrinsics = file("extrinsics.yml");
  {
    cv::FileStorage fs(intrinsics, cv::FileStorage::WRITE);
    fs << "M1" << cv::Mat(head.cameras[0].camera_matrix) << "D1" << cv::Mat(head.cameras[0].distortion)
       << "M2" << cv::Mat(head.cameras[1].camera_matrix) << "D2" << cv::Mat(head.cameras[1].distortion);
  }
  {
    cv::FileStorage fs(extrinsics, cv::FileStorage::WRITE);
    fs << "R" << cv::Mat(head.cameras[1].rotation) << "T" << cv::Mat(head.cameras[1].translation);
  }
  RigCalibration loaded = loadRigCalibration({intrinsics, extrinsics});
  EXPECT_EQ(loaded.cameras[0].size, cv::Size());
  loaded = withImageSizes(loaded, {{640, 480}, {640, 480}});
  for (size_t k = 0; k < 2; ++k) expectSameCamera(loaded.cameras[k], head.cameras[k], 1e-12);
  EXPECT_THROW(withImageSizes(loaded, {{320, 240}, {640, 480}}), RectificationError);
}

std::string matrixYaml(const std::string& name, const cv::Mat& m) {
  std::ostringstream text;
  text.precision(17);
  text << name << ":\n  rows: " << m.rows << "\n  cols: " << m.cols << "\n  data: [";
  for (int i = 0; i < static_cast<int>(m.total()); ++i) text << (i ? ", " : "") << m.at<double>(i);
  text << "]\n";
  return text.str();
}

TEST_F(CalibrationFilesTest, RosCameraInfoPairGivesTheRelativePoseBack) {
  // camera_calibration writes each camera's R (raw -> rectified) and P; stereoRectify makes them.
  const RigCalibration head = rawBinocularHead();
  const auto& left = head.cameras[0];
  const auto& right = head.cameras[1];
  cv::Mat R1, R2, P1, P2, Q;
  cv::stereoRectify(left.camera_matrix, left.distortion, right.camera_matrix, right.distortion,
                    left.size, right.rotation, right.translation, R1, R2, P1, P2, Q);
  std::vector<std::string> paths;
  int index = 0;
  for (const auto& [camera, R, P] :
       {std::tuple{left, R1, P1}, std::tuple{right, R2, P2}}) {
    std::ostringstream yaml;
    yaml << "image_width: 640\nimage_height: 480\ncamera_name: narrow_stereo/" << index << "\n"
         << matrixYaml("camera_matrix", cv::Mat(camera.camera_matrix))
         << "distortion_model: plumb_bob\n"
         << matrixYaml("distortion_coefficients", cv::Mat(camera.distortion).reshape(1, 1))
         << matrixYaml("rectification_matrix", R) << matrixYaml("projection_matrix", P);
    paths.push_back(file("camera" + std::to_string(index++) + ".yaml", yaml.str()));
  }
  const RigCalibration loaded = loadRigCalibration(paths);
  ASSERT_EQ(loaded.cameras.size(), 2u);
  expectSameCamera(loaded.cameras[0], left, 1e-9);
  expectSameCamera(loaded.cameras[1], right, 1e-9);
}

TEST_F(CalibrationFilesTest, MrptStereoCameraIni) {
  const RigCalibration head = rawBinocularHead();
  mrpt::img::TStereoCamera stereo;
  for (auto* camera : {&stereo.leftCamera, &stereo.rightCamera}) {
    const CameraCalibration& source = head.cameras[camera == &stereo.leftCamera ? 0 : 1];
    camera->ncols = 640, camera->nrows = 480;
    camera->setIntrinsicParamsFromValues(source.camera_matrix(0, 0), source.camera_matrix(1, 1),
                                         source.camera_matrix(0, 2), source.camera_matrix(1, 2));
    std::vector<double> d = source.distortion;
    d.resize(5, 0.0);
    camera->setDistortionPlumbBob(d[0], d[1], d[2], d[3], d[4]);
  }
  // The right camera's optical frame in the left one's: X_left = R^T X_right + c.
  const cv::Matx33d to_left = head.cameras[1].rotation.t();
  const cv::Vec3d centre = head.cameras[1].centreInReference();
  mrpt::math::CMatrixDouble33 rotation;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) rotation(r, c) = to_left(r, c);
  stereo.rightCameraPose = mrpt::poses::CPose3DQuat(mrpt::poses::CPose3D(
      rotation, mrpt::math::CVectorFixedDouble<3>({centre[0], centre[1], centre[2]}))).asTPose();
  mrpt::config::CConfigFileMemory memory;
  stereo.saveToConfigFile("CAMERA_PARAMS", memory);
  const RigCalibration loaded = loadRigCalibration({file("stereo.ini", memory.getContent())});
  expectSameCamera(loaded.cameras[0], head.cameras[0], 1e-6);
  expectSameCamera(loaded.cameras[1], head.cameras[1], 1e-6);
}

TEST_F(CalibrationFilesTest, EurocSensorYamlOfTheClip) {
  const std::string clip = std::string(STEREONAV_SHARED_DATA_DIR) + "/euroc-v1-01-clip";
  if (!std::filesystem::exists(clip + "/cam0/sensor.yaml")) {
    GTEST_SKIP() << clip << " is absent (the EuRoC clip is not part of the project)";
  }
  const RigCalibration loaded =
      loadRigCalibration({clip + "/cam0/sensor.yaml", clip + "/cam1/sensor.yaml"});
  ASSERT_EQ(loaded.cameras.size(), 2u);
  EXPECT_EQ(loaded.cameras[1].size, cv::Size(752, 480));
  EXPECT_DOUBLE_EQ(loaded.cameras[1].camera_matrix(0, 2), 379.999);
  EXPECT_DOUBLE_EQ(loaded.cameras[0].distortion[0], -0.28340811);
  // The README: baseline about 0.110 m, cam1 to the right of cam0.
  const cv::Vec3d centre = loaded.cameras[1].centreInReference();
  EXPECT_NEAR(cv::norm(centre), 0.110, 0.002);
  EXPECT_GT(centre[0], 0.10);
}

TEST_F(CalibrationFilesTest, BadFilesAreNamedWithTheReason) {
  const auto message = [](const std::vector<std::string>& paths) {
    try {
      loadRigCalibration(paths);
    } catch (const RectificationError& e) {
      return std::string(e.what());
    }
    return std::string("not rejected");
  };
  const std::string missing = file("missing.yaml");
  EXPECT_NE(message({missing}).find(missing + ": cannot read"), std::string::npos);
  const std::string unknown = file("unknown.yaml", "%YAML:1.0\nfoo: 1\n");
  EXPECT_NE(message({unknown}).find("not a calibration"), std::string::npos);
  const std::string short_matrix =
      file("short.yaml", "%YAML:1.0\nM1: [1, 2]\nD1: [0]\nM2: [1]\nD2: [0]\nR: [1]\nT: [1]\n");
  EXPECT_NE(message({short_matrix}).find("'M1' has 2 numbers, expected 9"), std::string::npos);
  const std::string fisheye = file("fisheye.yaml", "image_width: 10\nimage_height: 10\n" +
                                                        matrixYaml("camera_matrix", cv::Mat(cv::Matx33d::eye())) +
                                                        "distortion_model: equidistant\n" +
                                                        matrixYaml("projection_matrix", cv::Mat(cv::Matx34d::eye())));
  EXPECT_NE(message({fisheye}).find("'equidistant' is not supported"), std::string::npos);
}

}  // namespace
}  // namespace stereonav
