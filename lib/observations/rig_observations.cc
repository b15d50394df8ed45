#include "observations/rig_observations.h"

#include <mrpt/poses/CPose3D.h>
#include <mrpt/poses/CPose3DQuat.h>

#include <cmath>

#include "observations/external_images.h"

namespace stereonav {
namespace {

using mrpt::img::CImage;
using mrpt::img::TCamera;
using mrpt::poses::CPose3D;
using mrpt::poses::CPose3DQuat;

// Poses pass through quaternions in CObservationStereoImages; anything closer than this is the
// same rectified geometry.
constexpr double kGeometryTolerance = 1e-6;

TCamera toTCamera(const PinholeCamera& camera, const std::string& name) {
  TCamera t;
  t.ncols = static_cast<uint32_t>(camera.width);
  t.nrows = static_cast<uint32_t>(camera.height);
  t.setIntrinsicParamsFromValues(camera.focal_px, camera.focal_px, camera.cx, camera.cy);
  t.cameraName = name;
  return t;
}

// The optical frame of a secondary camera: the reference's, moved along its own x and y axes.
CPose3D secondaryPose(const CameraRig& rig, const SecondaryCamera& secondary) {
  return rig.pose_on_robot +
         CPose3D(secondary.bx * rig.baseline_m, secondary.by * rig.baseline_m, 0, 0, 0, 0);
}

bool endsWith(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() &&
         text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

void requireCalibration(const TCamera& camera, const std::string& which) {
  if (camera.ncols == 0 || camera.nrows == 0 || !(camera.fx() > 0) || !(camera.fy() > 0)) {
    throw ObservationRejected(RejectReason::kMissingCalibration,
                              which + ": no calibration (focal length or image size missing)");
  }
}

// All cameras of a rectified rig share the reference's pinhole intrinsics and have no distortion.
void requireRectifiedLike(const TCamera& camera, const TCamera& reference,
                          const std::string& which) {
  bool distorted = false;
  for (const double k : camera.dist) distorted = distorted || k != 0.0;
  const auto near = [](double a, double b) { return std::abs(a - b) <= kGeometryTolerance; };
  if (distorted || !near(camera.fx(), camera.fy()) || !near(camera.fx(), reference.fx()) ||
      !near(camera.cx(), reference.cx()) || !near(camera.cy(), reference.cy()) ||
      camera.ncols != reference.ncols || camera.nrows != reference.nrows) {
    throw ObservationRejected(RejectReason::kNotRectified,
                              which +
                                  ": not a rectified camera (distortion, non-square pixels or "
                                  "intrinsics differing from the reference camera)");
  }
}

cv::Mat loadImage(const CImage& image, const TCamera& camera, const std::string& images_directory,
                  const std::string& which) {
  cv::Mat pixels = imagePixels(image, images_directory);
  if (pixels.empty()) {
    throw ObservationRejected(
        RejectReason::kMissingImage,
        which + ": image missing (" +
            (image.isExternallyStored() ? images_directory + "/" + image.getExternalStorageFile()
                                        : std::string("empty embedded image")) +
            ")");
  }
  if (pixels.cols != static_cast<int>(camera.ncols) ||
      pixels.rows != static_cast<int>(camera.nrows)) {
    throw ObservationRejected(
        RejectReason::kWrongImageFormat,
        which + ": image is " + std::to_string(pixels.cols) + "x" + std::to_string(pixels.rows) +
            ", its camera is " + std::to_string(camera.ncols) + "x" + std::to_string(camera.nrows));
  }
  return pixels;
}

// Offset of `camera_pose` from `reference_pose` in the reference optical frame; rejects a camera
// that is rotated or moved along the optical axis (not coplanar, paper section 2.1).
mrpt::math::TPoint3D coplanarOffset(const CPose3D& reference_pose, const CPose3D& camera_pose,
                                    const std::string& which) {
  const CPose3D relative = camera_pose - reference_pose;
  const bool aligned = std::abs(relative.yaw()) <= kGeometryTolerance &&
                       std::abs(relative.pitch()) <= kGeometryTolerance &&
                       std::abs(relative.roll()) <= kGeometryTolerance &&
                       std::abs(relative.z()) <= kGeometryTolerance;
  if (!aligned) {
    throw ObservationRejected(RejectReason::kNotRectified,
                              which + ": camera not coplanar with and parallel to the reference");
  }
  return relative.translation();
}

}  // namespace

std::string cameraLabel(const std::string& pair_label, size_t camera_index) {
  return pair_label + "_CAM" + std::to_string(camera_index);
}

RigObservations toRigObservations(const RigFrame& frame, const std::string& pair_label) {
  checkRigFrame(frame);
  const CameraRig& rig = frame.rig;
  if (rig.secondaries.empty() || rig.secondaries[0].by != 0.0 || rig.secondaries[0].bx == 0.0) {
    throw std::invalid_argument(
        "rig frame: the first secondary camera must sit beside the reference (by = 0, bx != 0) to "
        "form an MRPT stereo pair");
  }
  const SecondaryCamera& partner = rig.secondaries[0];
  const bool reference_is_left = partner.bx > 0;

  RigObservations observations;
  auto& pair = *(observations.pair = mrpt::obs::CObservationStereoImages::Create());
  pair.timestamp = frame.timestamp;
  pair.sensorLabel = pair_label;
  const TCamera reference_camera = toTCamera(rig.reference, cameraLabel(pair_label, 0));
  const TCamera partner_camera = toTCamera(rig.reference, cameraLabel(pair_label, 1));
  const CImage reference_image(frame.reference, mrpt::img::SHALLOW_COPY);
  const CImage partner_image(frame.secondaries[0], mrpt::img::SHALLOW_COPY);
  pair.leftCamera = reference_is_left ? reference_camera : partner_camera;
  pair.rightCamera = reference_is_left ? partner_camera : reference_camera;
  pair.imageLeft = reference_is_left ? reference_image : partner_image;
  pair.imageRight = reference_is_left ? partner_image : reference_image;
  pair.hasImageRight = true;
  pair.hasImageDisparity = false;
  pair.cameraPose =
      CPose3DQuat(reference_is_left ? rig.pose_on_robot : secondaryPose(rig, partner));
  pair.rightCameraPose = CPose3DQuat(CPose3D(std::abs(partner.bx) * rig.baseline_m, 0, 0, 0, 0, 0));

  for (size_t i = 1; i < rig.secondaries.size(); ++i) {
    auto extra = mrpt::obs::CObservationImage::Create();
    extra->timestamp = frame.timestamp;
    extra->sensorLabel = cameraLabel(pair_label, i + 1);
    extra->cameraParams = toTCamera(rig.reference, extra->sensorLabel);
    extra->cameraPose = secondaryPose(rig, rig.secondaries[i]);
    extra->image = CImage(frame.secondaries[i], mrpt::img::SHALLOW_COPY);
    observations.extra_cameras.push_back(extra);
  }
  return observations;
}

RigFrame fromRigObservations(const mrpt::obs::CObservationStereoImages& pair,
                             const std::vector<mrpt::obs::CObservationImage::Ptr>& extra_cameras,
                             const std::string& images_directory, PairReference unnamed_reference) {
  const std::string& label = pair.sensorLabel;
  requireCalibration(pair.leftCamera, label + " left camera");
  requireCalibration(pair.rightCamera, label + " right camera");
  if (!pair.hasImageRight) {
    throw ObservationRejected(RejectReason::kWrongCameraCount, label + ": no right image");
  }
  const double baseline = CPose3D(pair.rightCameraPose).translation().norm();
  if (!(baseline > 0)) {
    throw ObservationRejected(RejectReason::kMissingCalibration, label + ": zero stereo baseline");
  }

  bool reference_is_left = unnamed_reference == PairReference::kLeft;
  if (endsWith(pair.leftCamera.cameraName, "_CAM0")) reference_is_left = true;
  if (endsWith(pair.rightCamera.cameraName, "_CAM0")) reference_is_left = false;
  const TCamera& reference = reference_is_left ? pair.leftCamera : pair.rightCamera;
  requireRectifiedLike(pair.leftCamera, reference, label + " left camera");
  requireRectifiedLike(pair.rightCamera, reference, label + " right camera");

  const CPose3D left_pose(pair.cameraPose);
  const CPose3D right_pose = left_pose + CPose3D(pair.rightCameraPose);
  const auto right_offset = coplanarOffset(left_pose, right_pose, label + " right camera");
  if (std::abs(right_offset.y) > kGeometryTolerance || !(right_offset.x > 0)) {
    throw ObservationRejected(RejectReason::kNotRectified,
                              label + ": right camera not on the left camera's +x axis");
  }

  RigFrame frame;
  frame.timestamp = pair.timestamp;
  CameraRig& rig = frame.rig;
  rig.reference.width = static_cast<int>(reference.ncols);
  rig.reference.height = static_cast<int>(reference.nrows);
  rig.reference.focal_px = reference.fx();
  rig.reference.cx = reference.cx();
  rig.reference.cy = reference.cy();
  rig.baseline_m = baseline;
  rig.pose_on_robot = reference_is_left ? left_pose : right_pose;
  rig.secondaries = {SecondaryCamera{reference_is_left ? 1.0 : -1.0, 0.0}};
  if (const std::string problem = implausibleRig(rig); !problem.empty()) {
    throw ObservationRejected(RejectReason::kMissingCalibration, label + ": implausible calibration: " + problem);
  }

  const cv::Mat left =
      loadImage(pair.imageLeft, pair.leftCamera, images_directory, label + " left");
  const cv::Mat right =
      loadImage(pair.imageRight, pair.rightCamera, images_directory, label + " right");
  frame.reference = reference_is_left ? left : right;
  frame.secondaries = {reference_is_left ? right : left};

  for (const auto& extra : extra_cameras) {
    const std::string& which = extra->sensorLabel;
    requireCalibration(extra->cameraParams, which);
    requireRectifiedLike(extra->cameraParams, reference, which);
    const auto offset = coplanarOffset(rig.pose_on_robot, extra->cameraPose, which);
    rig.secondaries.push_back({offset.x / baseline, offset.y / baseline});
    if (const std::string problem = implausibleRig(rig); !problem.empty()) {
      throw ObservationRejected(RejectReason::kMissingCalibration, which + ": implausible calibration: " + problem);
    }
    frame.secondaries.push_back(
        loadImage(extra->image, extra->cameraParams, images_directory, which));
  }
  try {
    checkRigFrame(frame);
  } catch (const std::invalid_argument& e) {
    throw ObservationRejected(RejectReason::kWrongImageFormat, label + ": " + e.what());
  }
  return frame;
}

}  // namespace stereonav
