#include "observations/rig_observations.h"

#include <mrpt/poses/CPose3D.h>
#include <mrpt/poses/CPose3DQuat.h>

#include <cmath>

#include "observations/external_images.h"
#include "rectification/calibration_files.h"

namespace stereonav {
namespace {

using mrpt::img::CImage;
using mrpt::img::TCamera;

// A calibration within physical sense (rig/camera_rig.h), checked on the rig the frame will be
// matched with, so a damaged or extreme recorded calibration cannot reach the matcher's sizes.
RigFrame checkedPlausible(RigFrame frame, const std::string& label) {
  if (const std::string problem = implausibleRig(frame.rig); !problem.empty()) {
    throw ObservationRejected(RejectReason::kMissingCalibration, label + ": implausible calibration: " + problem);
  }
  return frame;
}
using mrpt::poses::CPose3D;
using mrpt::poses::CPose3DQuat;

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

// `camera` at `pose` (its optical frame, in the reference camera's optical frame).
CameraCalibration placedCamera(const TCamera& camera, const CPose3D& pose, const std::string& which) {
  try {
    CameraCalibration calibration = cameraCalibrationOf(camera);
    placeCamera(calibration, pose);
    return calibration;
  } catch (const RectificationError& e) {
    throw ObservationRejected(RejectReason::kNotRectified,
                              which + ": cannot be rectified: " + e.what());
  }
}

cv::Mat loadImage(const CImage& image, const std::string& images_directory,
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
  return pixels;
}

}  // namespace

std::string cameraLabel(const std::string& pair_label, size_t camera_index) {
  return pair_label + "_CAM" + std::to_string(camera_index);
}

bool formsStereoPair(const CameraRig& rig) {
  return !rig.secondaries.empty() && rig.secondaries[0].by == 0.0 && rig.secondaries[0].bx != 0.0;
}

RigObservations toRigObservations(const RigFrame& frame, const std::string& pair_label) {
  checkRigFrame(frame);
  const CameraRig& rig = frame.rig;
  if (!formsStereoPair(rig)) {
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
                             const std::string& images_directory, PairReference unnamed_reference,
                             FrameRectifier& rectifier) {
  const std::string& label = pair.sensorLabel;
  if (!pair.hasImageRight) {
    throw ObservationRejected(RejectReason::kWrongCameraCount, label + ": no right image");
  }
  const bool recorded_calibration = !rectifier.hasCalibrationFile();
  if (recorded_calibration) {
    requireCalibration(pair.leftCamera, label + " left camera");
    requireCalibration(pair.rightCamera, label + " right camera");
    if (!(CPose3D(pair.rightCameraPose).translation().norm() > 0)) {
      throw ObservationRejected(RejectReason::kMissingCalibration, label + ": zero stereo baseline");
    }
  }

  bool reference_is_left = unnamed_reference == PairReference::kLeft;
  if (endsWith(pair.leftCamera.cameraName, "_CAM0")) reference_is_left = true;
  if (endsWith(pair.rightCamera.cameraName, "_CAM0")) reference_is_left = false;

  const CPose3D left_pose(pair.cameraPose);
  const CPose3D right_pose = left_pose + CPose3D(pair.rightCameraPose);
  RigCalibration recorded;
  recorded.reference_pose_on_robot = reference_is_left ? left_pose : right_pose;
  std::vector<cv::Mat> images{
      loadImage(pair.imageLeft, images_directory, label + " left"),
      loadImage(pair.imageRight, images_directory, label + " right")};
  if (recorded_calibration) {
    recorded.cameras = {placedCamera(pair.leftCamera, CPose3D(), label + " left camera"),
                        placedCamera(pair.rightCamera, CPose3D(pair.rightCameraPose),
                                     label + " right camera")};
    if (!reference_is_left) recorded = withReference(recorded, 1);
  }
  if (!reference_is_left) std::swap(images[0], images[1]);

  for (const auto& extra : extra_cameras) {
    const std::string& which = extra->sensorLabel;
    if (recorded_calibration) {
      requireCalibration(extra->cameraParams, which);
      recorded.cameras.push_back(placedCamera(
          extra->cameraParams, extra->cameraPose - recorded.reference_pose_on_robot, which));
    }
    images.push_back(loadImage(extra->image, images_directory, which));
  }
  return checkedPlausible(rectifier.frame(recorded, images, pair.timestamp, label, reference_is_left ? 0 : 1), label);
}

RigFrame fromCameraImages(const std::vector<mrpt::obs::CObservationImage::Ptr>& cameras,
                          const std::string& images_directory, FrameRectifier& rectifier) {
  const std::string label = cameras.at(0)->sensorLabel;
  RigCalibration recorded;
  recorded.reference_pose_on_robot = cameras[0]->cameraPose;
  std::vector<cv::Mat> images;
  for (const auto& camera : cameras) {
    const std::string& which = camera->sensorLabel;
    if (!rectifier.hasCalibrationFile()) {
      requireCalibration(camera->cameraParams, which);
      recorded.cameras.push_back(placedCamera(
          camera->cameraParams, camera->cameraPose - recorded.reference_pose_on_robot, which));
    }
    images.push_back(loadImage(camera->image, images_directory, which));
  }
  return checkedPlausible(rectifier.frame(recorded, images, cameras[0]->timestamp, label), label);
}

}  // namespace stereonav
