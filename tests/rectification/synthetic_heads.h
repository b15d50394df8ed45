#pragma once

#include <mrpt/core/bits_math.h>

#include <opencv2/calib3d.hpp>
#include <opencv2/core.hpp>
#include <vector>

#include "rectification/rig_calibration.h"

namespace stereonav {

// Calibrated heads with everything a real one has: distortion, intrinsics differing between the
// cameras, and partners turned and offset away from the ideal rectified layout.
inline CameraCalibration rawCamera(double fx, double fy, double cx, double cy,
                                   std::vector<double> distortion) {
  CameraCalibration camera;
  camera.size = {640, 480};
  camera.camera_matrix = cv::Matx33d(fx, 0, cx, 0, fy, cy, 0, 0, 1);
  camera.distortion = std::move(distortion);
  return camera;
}

// `camera` with its optical frame turned by `rotation_vector` (Rodrigues, radians) and its
// centre at `centre`, both in the reference camera's frame.
inline CameraCalibration placed(CameraCalibration camera, const cv::Vec3d& rotation_vector,
                                const cv::Vec3d& centre) {
  cv::Matx33d turn;
  cv::Rodrigues(rotation_vector, turn);
  camera.rotation = turn.t();  // X_k = R^T (X_ref - c)
  camera.translation = -(camera.rotation * centre);
  return camera;
}

inline RigCalibration rawBinocularHead() {
  RigCalibration head;
  head.cameras = {rawCamera(500, 502, 322, 236, {-0.12, 0.03, 0.001, -0.0005}),
                  placed(rawCamera(495, 497, 315, 245, {-0.1, 0.02, -0.0007, 0.0004, 0.001}),
                         {0.01, -0.03, 0.02}, {0.12, 0.004, -0.003})};
  return head;
}

// Triclops-like L: reference = right camera, partner on its left, third camera above.
inline RigCalibration rawLShapedHead() {
  RigCalibration head;
  head.cameras = {rawCamera(500, 502, 322, 236, {-0.12, 0.03, 0.001, -0.0005}),
                  placed(rawCamera(495, 497, 315, 245, {-0.1, 0.02, 0, 0}), {0.01, -0.02, 0.015},
                         {-0.10, 0.003, 0.002}),
                  placed(rawCamera(505, 503, 330, 240, {-0.11, 0.025, 0, 0}),
                         {-0.015, 0.01, -0.01}, {0.004, -0.10, -0.002})};
  return head;
}

// Where a point X (reference camera frame) appears in camera k's raw image.
inline cv::Point2f projectRaw(const CameraCalibration& camera, const cv::Vec3d& point) {
  cv::Vec3d rotation_vector;
  cv::Rodrigues(camera.rotation, rotation_vector);
  std::vector<cv::Point2d> image;
  cv::projectPoints(std::vector<cv::Point3d>{cv::Point3d(point)}, rotation_vector,
                    camera.translation, camera.camera_matrix, camera.distortion, image);
  return cv::Point2f(image[0]);
}

// Scene points 1.5 to 6 m ahead, spread over the middle of the reference's view.
inline std::vector<cv::Vec3d> scenePoints(int count) {
  cv::RNG random(7);
  std::vector<cv::Vec3d> points;
  for (int i = 0; i < count; ++i) {
    const double z = random.uniform(1.5, 6.0);
    points.push_back({random.uniform(-0.35, 0.35) * z, random.uniform(-0.25, 0.25) * z, z});
  }
  return points;
}

}  // namespace stereonav
