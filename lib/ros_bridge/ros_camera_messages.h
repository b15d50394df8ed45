#pragma once

#include <mrpt/obs/CObservationImage.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>

#include <string>
#include <vector>

#include "observations/rig_frame.h"

namespace stereonav {

// How the head travels as ROS messages, in the conventions of stereo_image_proc and
// sensor_msgs/CameraInfo: an Image and a CameraInfo per camera, all stamped with the instant of
// the capture. K and D are the camera's own intrinsics and distortion; R turns the camera into the
// head's common rectified frame, and P = [f 0 cx Tx; 0 f cy Ty; 0 0 1 0] projects in that frame,
// with Tx = -f X and Ty = -f Y, where (X, Y) is the camera's centre in the left camera's rectified
// frame (metres, x right, y down). Rectified images (image_rect) carry D = 0 and R = I.
//
// Cameras, in message order: "left" and "right" (the pair), and "top" for the Triclops L-shape
// (paper section 2: the third camera sits above the reference).
constexpr size_t kMaxRosCameras = 3;
constexpr const char* kRosCameraNames[kMaxRosCameras] = {"left", "right", "top"};

struct RosCameraMessage {
  sensor_msgs::Image image;
  sensor_msgs::CameraInfo info;
};

// One frame as its cameras' messages: left, right, then top if the rig has a second secondary
// camera. The images are rectified, so D = 0, R = I and K = P's first three columns. Each camera's
// frame_id is "<frame_id_prefix>_<name>_optical". Throws std::invalid_argument if the rig's first
// secondary camera is not beside the reference or it has more than two secondary cameras.
std::vector<RosCameraMessage> toRosCameraMessages(const RigFrame& frame,
                                                  const std::string& frame_id_prefix);

// One camera's messages as MRPT records a camera, labelled `label`: the image (mono8 stays grey,
// any other encoding becomes BGR), K and D as its cameraParams, and as its cameraPose where the
// camera sits in the left camera's rectified frame (from R and P), so that the relative poses of
// a capture's cameras are their calibration (observations/rig_observations.h, fromCameraImages).
// Throws ObservationRejected: kWrongImageFormat for an encoding that cannot be converted or an
// image whose size is not its CameraInfo's, kMissingCalibration for a CameraInfo without focal
// length, kNotRectified for a distortion model other than plumb_bob or rational_polynomial.
mrpt::obs::CObservationImage::Ptr toCameraObservation(const sensor_msgs::Image& image,
                                                      const sensor_msgs::CameraInfo& info,
                                                      const std::string& label);

}  // namespace stereonav
