#include "ros_bridge/ros_camera_messages.h"

#include <cv_bridge/cv_bridge.h>
#include <mrpt/math/CMatrixFixed.h>
#include <mrpt/ros1bridge/time.h>
#include <sensor_msgs/distortion_models.h>
#include <sensor_msgs/image_encodings.h>

#include <algorithm>
#include <stdexcept>

#include "observations/rig_observations.h"

namespace stereonav {
namespace {

// Where a rig camera's centre is relative to the reference camera, metres along the reference
// image axes (camera_rig.h: SecondaryCamera).
struct CameraPlace {
  size_t rig_camera;  // 0 = reference, k = secondaries[k - 1]
  double x, y;
};

sensor_msgs::CameraInfo rectifiedCameraInfo(const PinholeCamera& camera, double tx_m, double ty_m) {
  sensor_msgs::CameraInfo info;
  info.width = static_cast<uint32_t>(camera.width);
  info.height = static_cast<uint32_t>(camera.height);
  info.distortion_model = sensor_msgs::distortion_models::PLUMB_BOB;
  info.D.assign(5, 0.0);
  info.K = {camera.focal_px, 0.0, camera.cx, 0.0, camera.focal_px, camera.cy, 0.0, 0.0, 1.0};
  info.R = {1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0};
  info.P = {camera.focal_px, 0.0, camera.cx, -camera.focal_px * tx_m,
            0.0, camera.focal_px, camera.cy, -camera.focal_px * ty_m,
            0.0, 0.0, 1.0, 0.0};
  return info;
}

// The camera's orientation in the rectified frame: R itself, which takes a point from the
// camera's coordinates to the rectified ones (OpenCV's stereoRectify R1/R2). An all-zero R (an
// uncalibrated camera, as camera_info_manager leaves it) is the identity.
mrpt::math::CMatrixDouble33 orientationInRectifiedFrame(const sensor_msgs::CameraInfo& info) {
  mrpt::math::CMatrixDouble33 orientation;
  const bool unset = std::all_of(info.R.begin(), info.R.end(), [](double v) { return v == 0.0; });
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) orientation(r, c) = unset ? (r == c ? 1.0 : 0.0) : info.R[3 * r + c];
  }
  return orientation;
}

}  // namespace

std::vector<RosCameraMessage> toRosCameraMessages(const RigFrame& frame,
                                                  const std::string& frame_id_prefix) {
  checkRigFrame(frame);
  const CameraRig& rig = frame.rig;
  if (!formsStereoPair(rig) || rig.secondaries.size() > kMaxRosCameras - 1) {
    throw std::invalid_argument(
        "a ROS stereo head is a left/right pair and at most one more camera: this rig has " +
        std::to_string(rig.secondaries.size() + 1) + " cameras");
  }
  std::vector<CameraPlace> places{{0, 0.0, 0.0}};
  for (size_t k = 0; k < rig.secondaries.size(); ++k) {
    places.push_back(
        {k + 1, rig.secondaries[k].bx * rig.baseline_m, rig.secondaries[k].by * rig.baseline_m});
  }
  if (places[1].x < places[0].x) std::swap(places[0], places[1]);  // left first
  const double left_x = places[0].x, left_y = places[0].y;

  const std_msgs::Header header = [&] {
    std_msgs::Header h;
    h.stamp = mrpt::ros1bridge::toROS(frame.timestamp);
    return h;
  }();
  std::vector<RosCameraMessage> messages;
  for (size_t i = 0; i < places.size(); ++i) {
    const CameraPlace& place = places[i];
    const cv::Mat& image = place.rig_camera == 0 ? frame.reference
                                                 : frame.secondaries[place.rig_camera - 1];
    RosCameraMessage message;
    message.info = rectifiedCameraInfo(rig.reference, place.x - left_x, place.y - left_y);
    message.info.header = header;
    message.info.header.frame_id = frame_id_prefix + "_" + kRosCameraNames[i] + "_optical";
    cv_bridge::CvImage converted(message.info.header,
                                 image.channels() == 1 ? sensor_msgs::image_encodings::MONO8
                                                       : sensor_msgs::image_encodings::BGR8,
                                 image);
    converted.toImageMsg(message.image);
    messages.push_back(std::move(message));
  }
  return messages;
}

mrpt::obs::CObservationImage::Ptr toCameraObservation(const sensor_msgs::Image& image,
                                                      const sensor_msgs::CameraInfo& info,
                                                      const std::string& label) {
  cv_bridge::CvImagePtr converted;
  try {
    const bool grey = image.encoding == sensor_msgs::image_encodings::MONO8;
    converted = cv_bridge::toCvCopy(image, grey ? sensor_msgs::image_encodings::MONO8
                                                : sensor_msgs::image_encodings::BGR8);
  } catch (const std::exception& e) {
    throw ObservationRejected(RejectReason::kWrongImageFormat,
                              label + ": image encoding '" + image.encoding + "': " + e.what());
  }
  if (info.width != image.width || info.height != image.height) {
    throw ObservationRejected(
        RejectReason::kWrongImageFormat,
        label + ": image is " + std::to_string(image.width) + "x" + std::to_string(image.height) +
            ", its CameraInfo " + std::to_string(info.width) + "x" + std::to_string(info.height));
  }
  if (!(info.K[0] > 0.0 && info.K[4] > 0.0 && info.P[0] > 0.0 && info.P[5] > 0.0)) {
    throw ObservationRejected(RejectReason::kMissingCalibration,
                              label + ": its CameraInfo has no focal length (K, P)");
  }
  const std::string& model = info.distortion_model;
  if (!model.empty() && model != sensor_msgs::distortion_models::PLUMB_BOB &&
      model != sensor_msgs::distortion_models::RATIONAL_POLYNOMIAL) {
    throw ObservationRejected(RejectReason::kNotRectified,
                              label + ": distortion model '" + model +
                                  "': only plumb_bob and rational_polynomial can be rectified");
  }

  auto observation = mrpt::obs::CObservationImage::Create();
  observation->sensorLabel = label;
  observation->timestamp = mrpt::ros1bridge::fromROS(image.header.stamp);
  observation->image = mrpt::img::CImage(converted->image, mrpt::img::DEEP_COPY);
  mrpt::img::TCamera& camera = observation->cameraParams;
  camera.ncols = info.width;
  camera.nrows = info.height;
  camera.setIntrinsicParamsFromValues(info.K[0], info.K[4], info.K[2], info.K[5]);
  // MRPT's plumb_bob holds OpenCV's k1 k2 p1 p2 k3 k4 k5 k6: ROS's plumb_bob and
  // rational_polynomial alike.
  camera.distortion = mrpt::img::DistortionModel::plumb_bob;
  for (size_t i = 0; i < std::min(info.D.size(), camera.dist.size()); ++i) camera.dist[i] = info.D[i];
  // A point p in this camera's frame is R p in the rectified frame, and R p + (X, Y, 0) in the
  // left camera's rectified frame: the camera's pose there is (R, (X, Y, 0)).
  mrpt::math::CVectorFixedDouble<3> centre;
  centre[0] = -info.P[3] / info.P[0];
  centre[1] = -info.P[7] / info.P[5];
  centre[2] = 0.0;
  observation->cameraPose =
      mrpt::poses::CPose3D(orientationInRectifiedFrame(info), centre);
  return observation;
}

}  // namespace stereonav
